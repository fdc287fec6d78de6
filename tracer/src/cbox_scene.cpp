// The external Cornell box (../shared/scenes/cbox): eight OBJ files without MTL, so
// the materials, the emitter and the camera come from the facts in its README.md.
#include <filesystem>

#include <hush/core/error.hpp>
#include <hush/tracer/scene_file.hpp>

namespace hush::tracer {

Scene loadCornellBoxObj(const std::string& folder) {
    Scene scene;
    scene.name = "cbox";
    scene.sceneScale = 0.001f;   // the files are in millimetres
    // Diffuse RGB reflectances from the README; all matte (specular 0).
    scene.materials = {
        Material{.name = "white", .albedo = {0.885809f, 0.698859f, 0.666422f}},
        Material{.name = "red", .albedo = {0.570068f, 0.0430135f, 0.0443706f}},
        Material{.name = "green", .albedo = {0.105421f, 0.37798f, 0.076425f}},
        Material{.name = "box", .albedo = {0.45f, 0.30f, 0.90f}},
        Material{.name = "light", .albedo = {0.936461f, 0.740433f, 0.705267f}, .emission = {18.387f, 10.9873f, 2.75357f}},
    };
    const struct {
        const char* file;
        const char* material;
    } parts[] = {
        {"cbox_floor", "white"},       {"cbox_ceiling", "white"},  {"cbox_back", "white"},
        {"cbox_redwall", "red"},       {"cbox_greenwall", "green"}, {"cbox_smallbox", "box"},
        {"cbox_largebox", "box"},      {"cbox_luminaire", "light"},
    };
    for (const auto& part : parts) {
        // The files carry no usemtl; make the README's material the default one and
        // ignore any material statements a modified copy might add.
        ObjOptions options;
        options.defaultMaterial = part.material;
        options.loadMaterials = false;
        const std::string path = (std::filesystem::path(folder) / (std::string(part.file) + ".obj")).string();
        std::vector<Mesh> meshes = loadObj(path, scene.materials, options);
        if (meshes.empty()) throw Error(ErrorKind::InvalidArgument, path + ": has no faces");
        for (Mesh& m : meshes) {
            // The luminaire is coplanar with the ceiling's hole; the README moves it
            // down 0.5 mm so that it sits just below the ceiling.
            if (std::string_view(part.file) == "cbox_luminaire")
                for (glm::vec3& p : m.positions) p.y -= 0.5f;
            m.name = meshes.size() == 1 ? std::string(part.file) : std::string(part.file) + "/" + m.name;
            scene.meshes.push_back(std::move(m));
        }
    }
    scene.camera.name = "cbox";
    scene.camera.nearPlane = 10.0f;
    scene.camera.farPlane = 2800.0f;
    // The README's fov is "on the smaller axis": vertical for the landscape frames hush renders.
    scene.camera.keys = {CameraKey{.time = 0.0f,
                                   .position = {278.0f, 273.0f, -800.0f},
                                   .target = {278.0f, 273.0f, -799.0f},
                                   .up = {0.0f, 1.0f, 0.0f},
                                   .verticalFovDegrees = 39.3077f}};
    scene.validate();
    return scene;
}

} // namespace hush::tracer
