#pragma once
// The built-in scenes, built procedurally in code (no data files), each stressing a
// different denoiser challenge; docs/scenes.md describes them.
//   cornell       the classic Cornell box (../shared/scenes/cbox/README.md), camera "dolly-pan"
//   room          an interior lit through a window by a sun and a sky, camera "walk"
//   glossy        GGX spheres from alpha 0.02 to 0.8 and mirrors, camera "orbit"
//   moving-light  static camera, a light moving between occluders, camera "static"
//   thin          grass, leaves and fence bars before a wall, camera "strafe"
#include <string>
#include <vector>

#include <hush/tracer/scene.hpp>

namespace hush::tracer {

// The names above, in that order.
std::vector<std::string> builtinSceneNames();

// Builds the named scene (deterministic: the same name gives the same scene).
// Throws hush::Error (NotFound) listing the valid names for any other name.
Scene makeBuiltinScene(const std::string& name);

// "cornell": the scene the CLI and samples use when none is named.
std::string defaultSceneName();

} // namespace hush::tracer
