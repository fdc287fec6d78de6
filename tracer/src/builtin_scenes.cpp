#include <hush/core/error.hpp>
#include <hush/tracer/builtin_scenes.hpp>

#include "mesh_builders.hpp"

namespace hush::tracer {

namespace {

struct BuiltinScene {
    const char* name;
    Scene (*make)();
};

// The one list of built-in scenes: names, order and factories stay together.
constexpr BuiltinScene kBuiltinScenes[] = {
    {"cornell", &build::makeCornellScene},
    {"room", &build::makeRoomScene},
    {"glossy", &build::makeGlossyScene},
    {"moving-light", &build::makeMovingLightScene},
    {"thin", &build::makeThinScene},
};

} // namespace

std::vector<std::string> builtinSceneNames() {
    std::vector<std::string> names;
    for (const auto& s : kBuiltinScenes) names.emplace_back(s.name);
    return names;
}

Scene makeBuiltinScene(const std::string& name) {
    for (const auto& s : kBuiltinScenes)
        if (name == s.name) return s.make();
    std::string list;
    for (const auto& s : kBuiltinScenes) list += (list.empty() ? "" : ", ") + std::string(s.name);
    throw Error(ErrorKind::NotFound, "unknown built-in scene '" + name + "'; the built-in scenes are: " + list);
}

std::string defaultSceneName() { return "cornell"; }

} // namespace hush::tracer
