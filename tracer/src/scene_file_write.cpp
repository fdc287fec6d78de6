// Scene -> JSON text in the format of docs/scene-format.md. Numbers go through
// double, which nlohmann prints with enough digits for every float to read back
// bit-exactly, so write -> parse is an exact round trip.
#include <set>

#include <nlohmann/json.hpp>

#include <hush/core/error.hpp>
#include <hush/tracer/scene_file.hpp>

namespace hush::tracer {

namespace {

using Json = nlohmann::ordered_json;   // keep the documented field order: easier to read and diff

Json vec(glm::vec3 v) { return Json::array({double(v.x), double(v.y), double(v.z)}); }

Json motion(const std::vector<Keyframe>& keys) {
    Json list = Json::array();
    for (const Keyframe& k : keys)
        list.push_back({{"time", double(k.time)}, {"translation", vec(k.translation)},
                        {"rotationYDegrees", double(k.rotationYDegrees)}});
    return list;
}

} // namespace

std::string writeSceneFile(const Scene& scene) {
    scene.validate();
    Json root;
    root["name"] = scene.name;
    root["framesPerSecond"] = double(scene.framesPerSecond);
    root["sceneScale"] = double(scene.sceneScale);
    // Meshes refer to materials by name, so names must identify them.
    std::set<std::string> names;
    Json materials = Json::array();
    for (const Material& m : scene.materials) {
        if (m.name.empty() || !names.insert(m.name).second)
            throw Error(ErrorKind::InvalidArgument, "writeSceneFile: scene '" + scene.name + "' has an empty or repeated material name '" +
                                                        m.name + "'; JSON meshes refer to materials by name");
        materials.push_back({{"name", m.name}, {"albedo", vec(m.albedo)}, {"specular", vec(m.specular)},
                             {"roughness", double(m.roughness)}, {"emission", vec(m.emission)},
                             {"doubleSidedEmission", m.doubleSidedEmission}});
    }
    root["materials"] = std::move(materials);
    Json meshes = Json::array();
    for (const Mesh& mesh : scene.meshes) {
        Json m;
        m["name"] = mesh.name;
        m["material"] = scene.materials[mesh.material].name;
        m["positions"] = Json::array();
        for (const glm::vec3& p : mesh.positions) m["positions"].push_back(vec(p));
        if (!mesh.normals.empty()) {
            m["normals"] = Json::array();
            for (const glm::vec3& n : mesh.normals) m["normals"].push_back(vec(n));
        }
        m["triangles"] = Json::array();
        for (const glm::uvec3& t : mesh.triangles) m["triangles"].push_back({t.x, t.y, t.z});
        if (!mesh.motion.empty()) m["motion"] = motion(mesh.motion);
        meshes.push_back(std::move(m));
    }
    root["meshes"] = std::move(meshes);
    root["sun"] = {{"direction", vec(scene.sun.direction)}, {"radiance", vec(scene.sun.radiance)},
                   {"angularRadiusDegrees", double(scene.sun.angularRadiusDegrees)}};
    if (!scene.sun.motion.empty()) root["sun"]["motion"] = motion(scene.sun.motion);
    root["sky"] = {{"zenith", vec(scene.sky.zenith)}, {"horizon", vec(scene.sky.horizon)}, {"ground", vec(scene.sky.ground)}};
    Json keys = Json::array();
    for (const CameraKey& k : scene.camera.keys)
        keys.push_back({{"time", double(k.time)}, {"position", vec(k.position)}, {"target", vec(k.target)},
                        {"up", vec(k.up)}, {"fov", double(k.verticalFovDegrees)}});
    root["camera"] = {{"name", scene.camera.name}, {"near", double(scene.camera.nearPlane)},
                      {"far", double(scene.camera.farPlane)}, {"keys", std::move(keys)}};
    // Names from OBJ files may hold any bytes; JSON needs UTF-8, so replace what is not.
    return root.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

} // namespace hush::tracer
