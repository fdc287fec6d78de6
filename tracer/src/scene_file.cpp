// The JSON scene file (docs/scene-format.md is the reference). Strict on purpose: an
// unknown field is an error listing the known ones, so a typo ("albdeo") never
// silently falls back to a default.
#include <cmath>
#include <filesystem>
#include <map>

#include <hush/rhi/error.hpp>
#include <hush/tracer/scene_file.hpp>

#include "json_fields.hpp"
#include "text_parse.hpp"

namespace hush::tracer {

namespace {

using detail::Json;
using detail::JsonFields;

class SceneReader {
public:
    SceneReader(const std::string& name, const FileReader& readFile) : f_(name), readFile_(readFile) {}

    Scene read(const Json& root) {
        f_.object(root, "", {"name", "framesPerSecond", "sceneScale", "materials", "meshes", "sun", "sky", "camera"});
        Scene scene;
        scene.name = root.contains("name") ? f_.string(root["name"], "name") : detail::fileStem(f_.file());
        if (root.contains("framesPerSecond")) scene.framesPerSecond = f_.positive(root["framesPerSecond"], "framesPerSecond");
        if (root.contains("sceneScale")) scene.sceneScale = f_.positive(root["sceneScale"], "sceneScale");
        if (root.contains("materials")) {
            const Json& list = f_.array(root["materials"], "materials");
            for (std::size_t i = 0; i < list.size(); ++i) material(list[i], JsonFields::item("materials", i), scene);
        }
        if (!root.contains("meshes")) f_.fail("", "missing field 'meshes'");
        const Json& meshes = f_.array(root["meshes"], "meshes");
        if (meshes.empty()) f_.fail("meshes", "needs at least one mesh");
        for (std::size_t i = 0; i < meshes.size(); ++i) mesh(meshes[i], JsonFields::item("meshes", i), i, scene);
        if (root.contains("sun")) scene.sun = sun(root["sun"], "sun");
        if (root.contains("sky")) scene.sky = sky(root["sky"], "sky");
        if (!root.contains("camera")) f_.fail("", "missing field 'camera'");
        scene.camera = camera(root["camera"], "camera");
        return scene;
    }

private:
    void material(const Json& v, const std::string& path, Scene& scene) {
        f_.object(v, path, {"name", "albedo", "specular", "roughness", "emission", "doubleSidedEmission"});
        if (!v.contains("name")) f_.fail(path, "missing field 'name'");
        Material m;
        m.name = f_.string(v["name"], JsonFields::child(path, "name"));
        if (const auto it = materialPaths_.find(m.name); it != materialPaths_.end())
            f_.fail(JsonFields::child(path, "name"), detail::quote(m.name) + " is already defined by " + it->second);
        materialPaths_.emplace(m.name, path);
        if (v.contains("albedo")) m.albedo = f_.colour(v["albedo"], JsonFields::child(path, "albedo"));
        if (v.contains("specular")) m.specular = f_.colour(v["specular"], JsonFields::child(path, "specular"));
        if (v.contains("roughness")) m.roughness = f_.nonNegative(v["roughness"], JsonFields::child(path, "roughness"));
        if (v.contains("emission")) m.emission = f_.colour(v["emission"], JsonFields::child(path, "emission"));
        if (v.contains("doubleSidedEmission"))
            m.doubleSidedEmission = f_.boolean(v["doubleSidedEmission"], JsonFields::child(path, "doubleSidedEmission"));
        scene.materials.push_back(std::move(m));
    }

    std::uint32_t materialIndex(const Json& v, const std::string& path, const Scene& scene) const {
        const std::string n = f_.string(v, path);
        for (std::size_t i = 0; i < scene.materials.size(); ++i)
            if (scene.materials[i].name == n) return static_cast<std::uint32_t>(i);
        f_.fail(path, "unknown material " + detail::quote(n));
    }

    void mesh(const Json& v, const std::string& path, std::size_t index, Scene& scene) {
        f_.object(v, path, {"name", "obj", "material", "positions", "normals", "triangles", "motion"});
        const bool fromObj = v.contains("obj");
        if (fromObj == v.contains("positions"))
            f_.fail(path, "needs exactly one of 'obj' (a file) or 'positions' + 'triangles' (inline)");
        std::vector<Keyframe> keys;
        if (v.contains("motion")) keys = motion(v["motion"], JsonFields::child(path, "motion"));
        std::string name;
        if (v.contains("name")) name = f_.string(v["name"], JsonFields::child(path, "name"));

        if (fromObj) {
            for (const char* inlineOnly : {"normals", "triangles"})
                if (v.contains(inlineOnly)) f_.fail(path, std::string("'") + inlineOnly + "' is only for inline meshes, not with 'obj'");
            std::vector<Mesh> loaded = objMeshes(v, path, scene);
            for (Mesh& m : loaded) {
                if (!name.empty()) m.name = loaded.size() == 1 ? name : name + "/" + m.name;
                m.motion = keys;
                scene.meshes.push_back(std::move(m));
            }
            return;
        }
        Mesh m;
        m.name = name.empty() ? "mesh" + std::to_string(index) : name;
        if (!v.contains("material")) f_.fail(path, "missing field 'material'");
        m.material = materialIndex(v["material"], JsonFields::child(path, "material"), scene);
        const std::string positionsPath = JsonFields::child(path, "positions");
        const Json& positions = f_.array(v["positions"], positionsPath);
        for (std::size_t i = 0; i < positions.size(); ++i)
            m.positions.push_back(f_.vec3(positions[i], JsonFields::item(positionsPath, i)));
        if (v.contains("normals")) {
            const std::string normalsPath = JsonFields::child(path, "normals");
            const Json& normals = f_.array(v["normals"], normalsPath);
            if (normals.size() != positions.size())
                f_.fail(normalsPath, "has " + std::to_string(normals.size()) + " normals for " +
                                         std::to_string(positions.size()) + " positions (one per position)");
            for (std::size_t i = 0; i < normals.size(); ++i) {
                const std::string p = JsonFields::item(normalsPath, i);
                m.normals.push_back(unit(f_.vec3(normals[i], p), p, "a normal needs a direction (zero length)"));
            }
        }
        const std::string trianglesPath = JsonFields::child(path, "triangles");
        if (!v.contains("triangles")) f_.fail(path, "missing field 'triangles'");
        const Json& triangles = f_.array(v["triangles"], trianglesPath);
        if (triangles.empty()) f_.fail(trianglesPath, "needs at least one triangle");
        for (std::size_t i = 0; i < triangles.size(); ++i) {
            const std::string p = JsonFields::item(trianglesPath, i);
            if (!triangles[i].is_array() || triangles[i].size() != 3) f_.fail(p, "must be an array of 3 vertex indices");
            glm::uvec3 t;
            for (int c = 0; c < 3; ++c) {
                const std::string cp = JsonFields::item(p, std::size_t(c));
                t[c] = f_.index(triangles[i][std::size_t(c)], cp);
                if (t[c] >= m.positions.size())
                    f_.fail(cp, "index " + std::to_string(t[c]) + " is past the " + std::to_string(m.positions.size()) +
                                    " positions");
            }
            m.triangles.push_back(t);
        }
        m.motion = std::move(keys);
        scene.meshes.push_back(std::move(m));
    }

    std::vector<Mesh> objMeshes(const Json& v, const std::string& path, Scene& scene) {
        const std::string objPath = JsonFields::child(path, "obj");
        const std::string written = f_.string(v["obj"], objPath);
        if (written.empty()) f_.fail(objPath, "must name a file");
        ObjOptions options;
        if (v.contains("material")) {
            // An override: every face of the file uses this material, whatever its usemtl says.
            const std::uint32_t m = materialIndex(v["material"], JsonFields::child(path, "material"), scene);
            options.defaultMaterial = scene.materials[m].name;
            options.loadMaterials = false;
        }
        if (!readFile_) f_.fail(objPath, "no file access when parsing from memory", ErrorKind::NotFound);
        std::vector<Mesh> meshes;
        try {
            const FileText obj = readFile_(written);
            // The OBJ's mtllib paths are relative to the OBJ, not to the scene file.
            const std::filesystem::path objFolder = std::filesystem::path(written).parent_path();
            const FileReader besideObj = [this, objFolder](const std::string& mtl) {
                return readFile_((objFolder / mtl).string());
            };
            meshes = parseObj(obj.text, obj.name, scene.materials, options, besideObj);
        } catch (const Error& e) {
            f_.fail(objPath, e.what(), e.kind());
        }
        if (meshes.empty()) f_.fail(objPath, detail::quote(written) + " has no faces");
        return meshes;
    }

    // Keyframes must be in time order: the interpolation in scene.cpp searches them.
    template <class Key, class ReadKey>
    std::vector<Key> keyframes(const Json& v, const std::string& path, ReadKey readKey) const {
        const Json& list = f_.array(v, path);
        std::vector<Key> keys;
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string p = JsonFields::item(path, i);
            Key k = readKey(list[i], p);
            if (!keys.empty() && k.time < keys.back().time)
                f_.fail(JsonFields::child(p, "time"), "keys must be in time order (" + std::to_string(k.time) +
                                                          " comes after " + std::to_string(keys.back().time) + ")");
            keys.push_back(k);
        }
        return keys;
    }

    std::vector<Keyframe> motion(const Json& v, const std::string& path) const {
        return keyframes<Keyframe>(v, path, [this](const Json& k, const std::string& p) {
            f_.object(k, p, {"time", "translation", "rotationYDegrees"});
            Keyframe key;
            if (!k.contains("time")) f_.fail(p, "missing field 'time'");
            key.time = f_.number(k["time"], JsonFields::child(p, "time"));
            if (k.contains("translation")) key.translation = f_.vec3(k["translation"], JsonFields::child(p, "translation"));
            if (k.contains("rotationYDegrees"))
                key.rotationYDegrees = f_.number(k["rotationYDegrees"], JsonFields::child(p, "rotationYDegrees"));
            return key;
        });
    }

    glm::vec3 direction(const Json& v, const std::string& path) const {
        return unit(f_.vec3(v, path), path, "must not be zero");
    }

    // Normalized, except that a vector already of unit length is kept bit for bit, so
    // that writeSceneFile -> parseSceneFile is an exact round trip.
    glm::vec3 unit(glm::vec3 d, const std::string& path, const char* zeroMessage) const {
        const double len = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
        if (!(len > 1e-30)) f_.fail(path, zeroMessage);
        if (std::fabs(len - 1.0) < 1e-6) return d;
        return glm::vec3(float(d.x / len), float(d.y / len), float(d.z / len));
    }

    Sun sun(const Json& v, const std::string& path) const {
        f_.object(v, path, {"direction", "radiance", "angularRadiusDegrees", "motion"});
        Sun s;
        if (v.contains("direction")) s.direction = direction(v["direction"], JsonFields::child(path, "direction"));
        if (v.contains("radiance")) s.radiance = f_.colour(v["radiance"], JsonFields::child(path, "radiance"));
        if (v.contains("angularRadiusDegrees")) {
            const std::string p = JsonFields::child(path, "angularRadiusDegrees");
            s.angularRadiusDegrees = f_.nonNegative(v["angularRadiusDegrees"], p);
            if (s.angularRadiusDegrees >= 90.0f) f_.fail(p, "must be below 90 degrees");
        }
        if (v.contains("motion")) s.motion = motion(v["motion"], JsonFields::child(path, "motion"));
        return s;
    }

    Sky sky(const Json& v, const std::string& path) const {
        f_.object(v, path, {"zenith", "horizon", "ground"});
        Sky s;
        if (v.contains("zenith")) s.zenith = f_.colour(v["zenith"], JsonFields::child(path, "zenith"));
        if (v.contains("horizon")) s.horizon = f_.colour(v["horizon"], JsonFields::child(path, "horizon"));
        if (v.contains("ground")) s.ground = f_.colour(v["ground"], JsonFields::child(path, "ground"));
        return s;
    }

    CameraPath camera(const Json& v, const std::string& path) const {
        f_.object(v, path, {"name", "keys", "near", "far"});
        CameraPath c;
        c.name = v.contains("name") ? f_.string(v["name"], JsonFields::child(path, "name")) : std::string("camera");
        if (v.contains("near")) c.nearPlane = f_.positive(v["near"], JsonFields::child(path, "near"));
        if (v.contains("far")) c.farPlane = f_.positive(v["far"], JsonFields::child(path, "far"));
        if (!(c.farPlane > c.nearPlane))
            f_.fail(path, "far (" + std::to_string(c.farPlane) + ") must be greater than near (" +
                              std::to_string(c.nearPlane) + ")");
        if (!v.contains("keys")) f_.fail(path, "missing field 'keys'");
        const std::string keysPath = JsonFields::child(path, "keys");
        c.keys = keyframes<CameraKey>(v["keys"], keysPath, [this](const Json& k, const std::string& p) {
            return cameraKey(k, p);
        });
        if (c.keys.empty()) f_.fail(keysPath, "needs at least one key");
        return c;
    }

    CameraKey cameraKey(const Json& k, const std::string& p) const {
        f_.object(k, p, {"time", "position", "target", "up", "fov"});
        CameraKey key;
        if (k.contains("time")) key.time = f_.number(k["time"], JsonFields::child(p, "time"));
        for (const char* required : {"position", "target"})
            if (!k.contains(required)) f_.fail(p, std::string("missing field '") + required + "'");
        key.position = f_.vec3(k["position"], JsonFields::child(p, "position"));
        key.target = f_.vec3(k["target"], JsonFields::child(p, "target"));
        if (k.contains("up")) key.up = direction(k["up"], JsonFields::child(p, "up"));
        if (k.contains("fov")) {
            key.verticalFovDegrees = f_.number(k["fov"], JsonFields::child(p, "fov"));
            if (!(key.verticalFovDegrees > 0.0f && key.verticalFovDegrees < 180.0f))
                f_.fail(JsonFields::child(p, "fov"), "vertical field of view must be in (0, 180) degrees");
        }
        // A view direction and an up vector along it leave the camera's roll undefined.
        const glm::dvec3 view = glm::dvec3(key.target) - glm::dvec3(key.position);
        if (!(glm::length(view) > 0.0)) f_.fail(p, "position and target must differ");
        if (!(glm::length(glm::cross(glm::normalize(view), glm::dvec3(key.up))) > 1e-6))
            f_.fail(JsonFields::child(p, "up"), "must not be parallel to the view direction (target - position)");
        return key;
    }

    JsonFields f_;
    const FileReader& readFile_;
    std::map<std::string, std::string> materialPaths_;
};

} // namespace

Scene parseSceneFile(std::string_view text, const std::string& name, const FileReader& readFile) {
    const Json root = detail::parseJson(text, name);
    Scene scene = SceneReader(name, readFile).read(root);
    try {
        scene.validate();
    } catch (const Error& e) {
        throw Error(e.kind(), name + ": " + e.what());
    }
    return scene;
}

Scene loadSceneFile(const std::string& path) {
    const FileText file = readTextFile(path);
    const std::string folder = std::filesystem::path(path).parent_path().string();
    return parseSceneFile(file.text, file.name, folderReader(folder.empty() ? "." : folder));
}

} // namespace hush::tracer
