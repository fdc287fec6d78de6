#pragma once
// Scenes from files: the JSON scene format of docs/scene-format.md, and the external
// Cornell box OBJ files of ../shared/scenes/cbox with the facts of their README.
#include <string>
#include <string_view>

#include <hush/tracer/obj_loader.hpp>
#include <hush/tracer/scene.hpp>

namespace hush::tracer {

// Reads a JSON scene file; "obj" paths inside it are relative to its folder.
// Errors name the file and the JSON path ("scene.json: meshes[2].material: unknown
// material 'gold'"), or file:line:column for JSON syntax errors. The result has
// passed Scene::validate().
Scene loadSceneFile(const std::string& path);

// The same from memory: `name` is used in errors and as the default scene name (its
// stem); `readFile` resolves "obj" paths (without one, an "obj" mesh is an error).
Scene parseSceneFile(std::string_view text, const std::string& name, const FileReader& readFile = {});

// Writes a scene as JSON text that parseSceneFile reads back to the same Scene
// (meshes inline, so OBJ origins are not kept). Material names must be unique;
// throws hush::Error otherwise or when the scene fails validate().
std::string writeSceneFile(const Scene& scene);

// The Cornell box of ../shared/scenes/cbox: its eight OBJ files (millimetres,
// sceneScale = 0.001), the README's materials, the luminaire moved down 0.5 mm and
// emitting RGB (18.387, 10.9873, 2.75357), and its camera as a one-key path named
// "cbox". Throws hush::Error(NotFound) when a file is missing.
Scene loadCornellBoxObj(const std::string& folder);

} // namespace hush::tracer
