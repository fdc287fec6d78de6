#include "scene_argument.hpp"

#include <filesystem>

#include <hush/core/error.hpp>
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

} // namespace hush::cli
