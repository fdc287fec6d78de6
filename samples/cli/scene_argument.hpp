#pragma once
// What `--scene` may name: a built-in scene, a JSON scene file, or a folder holding
// the Cornell box OBJ files (../shared/scenes/cbox).
#include <string>

#include <hush/tracer/scene.hpp>

namespace hush::cli {

tracer::Scene loadSceneArgument(const std::string& argument);
std::string sceneArgumentHelp();   // one paragraph for usage texts

// "640x360" -> {640, 360}; throws hush::Error naming the option.
void parseSize(const std::string& text, const char* option, uint32_t& width, uint32_t& height);
uint32_t parseCount(const std::string& text, const char* option, uint32_t minimum, uint32_t maximum);

} // namespace hush::cli
