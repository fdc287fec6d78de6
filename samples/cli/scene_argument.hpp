#pragma once
// What `--scene` may name: a built-in scene, a JSON scene file, or a folder holding
// the Cornell box OBJ files (../shared/scenes/cbox).
#include <string>

#include <hush/tracer/scene.hpp>

namespace hush::cli {

tracer::Scene loadSceneArgument(const std::string& argument);
std::string sceneArgumentHelp();   // one paragraph for usage texts

} // namespace hush::cli
