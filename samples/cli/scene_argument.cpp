#include "scene_argument.hpp"

#include <charconv>
#include <filesystem>

#include <hush/rhi/error.hpp>
#include <hush/tracer/builtin_scenes.hpp>
#include <hush/tracer/scene_file.hpp>

namespace hush::cli {

tracer::Scene loadSceneArgument(const std::string& argument) {
    namespace fs = std::filesystem;
    for (const auto& name : tracer::builtinSceneNames())
        if (name == argument) return tracer::makeBuiltinScene(name);
    if (argument.size() > 5 && argument.ends_with(".json")) return tracer::loadSceneFile(argument);
    if (fs::is_directory(argument) && fs::exists(fs::path(argument) / "cbox_luminaire.obj"))
        return tracer::loadCornellBoxObj(argument);
    std::string names;
    for (const auto& name : tracer::builtinSceneNames()) names += (names.empty() ? "" : ", ") + name;
    throw Error(ErrorKind::NotFound, "--scene '" + argument + "' is neither a built-in scene (" + names +
                                         "), a .json scene file, nor a folder with the Cornell box OBJ files");
}

std::string sceneArgumentHelp() {
    std::string names;
    for (const auto& name : tracer::builtinSceneNames()) names += (names.empty() ? "" : ", ") + name;
    return "a built-in scene (" + names + "; default " + tracer::defaultSceneName() +
           "), a JSON scene file (docs/scene-format.md), or a folder with the Cornell box OBJ files";
}

namespace {
bool parseUnsigned(std::string_view text, uint32_t& out) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
    return error == std::errc() && end == text.data() + text.size() && !text.empty();
}
} // namespace

void parseSize(const std::string& text, const char* option, uint32_t& width, uint32_t& height) {
    const auto x = text.find('x');
    if (x == std::string::npos || !parseUnsigned(std::string_view(text).substr(0, x), width) ||
        !parseUnsigned(std::string_view(text).substr(x + 1), height) || width == 0 || height == 0 || width > 16384 ||
        height > 16384)
        throw Error(ErrorKind::InvalidArgument, std::string(option) + " '" + text +
                                                    "' is not a size like 640x360 (1 to 16384 each)");
}

uint32_t parseCount(const std::string& text, const char* option, uint32_t minimum, uint32_t maximum) {
    uint32_t value = 0;
    if (!parseUnsigned(text, value) || value < minimum || value > maximum)
        throw Error(ErrorKind::InvalidArgument, std::string(option) + " '" + text + "' must be a whole number from " +
                                                    std::to_string(minimum) + " to " + std::to_string(maximum));
    return value;
}

} // namespace hush::cli
