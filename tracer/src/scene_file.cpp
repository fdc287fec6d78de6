// The JSON scene file (docs/scene-format.md is the reference). Strict on purpose: an
// unknown field is an error listing the known ones, so a typo ("albdeo") never
// silently falls back to a default.
#include <cmath>
#include <filesystem>
#include <map>

#include <hush/core/error.hpp>
#include <hush/core/json.hpp>
#include <hush/tracer/scene_file.hpp>

#include "text_parse.hpp"

namespace hush::tracer {

namespace {

using core::JsonObject;
using core::JsonValue;

glm::vec3 vec3(const JsonValue& v) {
    if (!v.json().is_array() || v.json().size() != 3) v.fail("must be an array of 3 numbers");
    return {v[0].number(), v[1].number(), v[2].number()};
}

glm::vec3 colour(const JsonValue& v) {
    if (!v.json().is_array() || v.json().size() != 3) v.fail("must be an RGB array of 3 numbers");
    return {v[0].nonNegative(), v[1].nonNegative(), v[2].nonNegative()};
}

// Normalized, except that a vector already of unit length is kept bit for bit, so
// that writeSceneFile -> parseSceneFile is an exact round trip.
glm::vec3 unit(glm::vec3 d, const JsonValue& where, const char* zeroMessage) {
    const double len = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
    if (!(len > 1e-30)) where.fail(zeroMessage);
    if (std::fabs(len - 1.0) < 1e-6) return d;
    return glm::vec3(float(d.x / len), float(d.y / len), float(d.z / len));
}

glm::vec3 direction(const JsonValue& v) { return unit(vec3(v), v, "must not be zero"); }

class SceneReader {
public:
    explicit SceneReader(const FileReader& readFile) : readFile_(readFile) {}

    Scene read(const JsonValue& rootValue) {
        JsonObject root(rootValue);
        root.only({"name", "framesPerSecond", "sceneScale", "materials", "meshes", "sun", "sky", "camera"});
        Scene scene;
        const auto name = root.get("name");
        scene.name = name ? name->string() : detail::fileStem(root.source());
        if (auto v = root.get("framesPerSecond")) scene.framesPerSecond = v->positive();
        if (auto v = root.get("sceneScale")) scene.sceneScale = v->positive();
        if (auto list = root.get("materials"))
            for (std::size_t i = 0; i < list->arraySize(); ++i) material((*list)[i], scene);
        const JsonValue meshes = root.require("meshes");
        if (meshes.arraySize() == 0) meshes.fail("needs at least one mesh");
        for (std::size_t i = 0; i < meshes.arraySize(); ++i) mesh(meshes[i], i, scene);
        if (auto v = root.get("sun")) scene.sun = sun(*v);
        if (auto v = root.get("sky")) scene.sky = sky(*v);
        scene.camera = camera(root.require("camera"));
        return scene;
    }

private:
    void material(const JsonValue& v, Scene& scene) {
        JsonObject o(v);
        o.only({"name", "albedo", "specular", "roughness", "emission", "doubleSidedEmission"});
        Material m;
        const JsonValue name = o.require("name");
        m.name = name.string();
        if (const auto it = materialPaths_.find(m.name); it != materialPaths_.end())
            name.fail(detail::quote(m.name) + " is already defined by " + it->second);
        materialPaths_.emplace(m.name, v.path());
        if (auto c = o.get("albedo")) m.albedo = colour(*c);
        if (auto c = o.get("specular")) m.specular = colour(*c);
        if (auto r = o.get("roughness")) m.roughness = r->nonNegative();
        if (auto c = o.get("emission")) m.emission = colour(*c);
        if (auto b = o.get("doubleSidedEmission")) m.doubleSidedEmission = b->boolean();
        scene.materials.push_back(std::move(m));
    }

    static std::uint32_t materialIndex(const JsonValue& v, const Scene& scene) {
        const std::string n = v.string();
        for (std::size_t i = 0; i < scene.materials.size(); ++i)
            if (scene.materials[i].name == n) return static_cast<std::uint32_t>(i);
        v.fail("unknown material " + detail::quote(n));
    }

    void mesh(const JsonValue& v, std::size_t index, Scene& scene) {
        JsonObject o(v);
        o.only({"name", "obj", "material", "positions", "normals", "triangles", "motion"});
        const bool fromObj = o.has("obj");
        if (fromObj == o.has("positions"))
            v.fail("needs exactly one of 'obj' (a file) or 'positions' + 'triangles' (inline)");
        std::vector<Keyframe> keys;
        if (auto m = o.get("motion")) keys = motion(*m);
        std::string name;
        if (auto n = o.get("name")) name = n->string();

        if (fromObj) {
            for (const char* inlineOnly : {"normals", "triangles"})
                if (o.has(inlineOnly)) v.fail(std::string("'") + inlineOnly + "' is only for inline meshes, not with 'obj'");
            std::vector<Mesh> loaded = objMeshes(o, scene);
            for (Mesh& m : loaded) {
                if (!name.empty()) m.name = loaded.size() == 1 ? name : name + "/" + m.name;
                m.motion = keys;
                scene.meshes.push_back(std::move(m));
            }
            return;
        }
        Mesh m;
        m.name = name.empty() ? "mesh" + std::to_string(index) : name;
        m.material = materialIndex(o.require("material"), scene);
        const JsonValue positions = o.require("positions");
        for (std::size_t i = 0; i < positions.arraySize(); ++i) m.positions.push_back(vec3(positions[i]));
        if (auto normals = o.get("normals")) {
            if (normals->arraySize() != m.positions.size())
                normals->fail("has " + std::to_string(normals->arraySize()) + " normals for " +
                              std::to_string(m.positions.size()) + " positions (one per position)");
            for (std::size_t i = 0; i < normals->arraySize(); ++i) {
                const JsonValue n = (*normals)[i];
                m.normals.push_back(unit(vec3(n), n, "a normal needs a direction (zero length)"));
            }
        }
        const JsonValue triangles = o.require("triangles");
        if (triangles.arraySize() == 0) triangles.fail("needs at least one triangle");
        for (std::size_t i = 0; i < triangles.arraySize(); ++i) m.triangles.push_back(triangle(triangles[i], m));
        m.motion = std::move(keys);
        scene.meshes.push_back(std::move(m));
    }

    static glm::uvec3 triangle(const JsonValue& v, const Mesh& m) {
        if (!v.json().is_array() || v.json().size() != 3) v.fail("must be an array of 3 vertex indices");
        glm::uvec3 t(0u);
        for (int c = 0; c < 3; ++c) {
            const JsonValue corner = v[std::size_t(c)];
            t[c] = corner.index();
            if (t[c] >= m.positions.size())
                corner.fail("index " + std::to_string(t[c]) + " is past the " + std::to_string(m.positions.size()) +
                            " positions");
        }
        return t;
    }

    std::vector<Mesh> objMeshes(JsonObject& o, Scene& scene) {
        const JsonValue obj = o.require("obj");
        const std::string written = obj.string();
        if (written.empty()) obj.fail("must name a file");
        ObjOptions options;
        if (auto material = o.get("material")) {
            // An override: every face of the file uses this material, whatever its usemtl says.
            options.defaultMaterial = scene.materials[materialIndex(*material, scene)].name;
            options.loadMaterials = false;
        }
        if (!readFile_) obj.fail("no file access when parsing from memory", ErrorKind::NotFound);
        std::vector<Mesh> meshes;
        try {
            const FileText text = readFile_(written);
            // The OBJ's mtllib paths are relative to the OBJ, not to the scene file.
            const std::filesystem::path objFolder = std::filesystem::path(written).parent_path();
            const FileReader besideObj = [this, objFolder](const std::string& mtl) {
                return readFile_((objFolder / mtl).string());
            };
            meshes = parseObj(text.text, text.name, scene.materials, options, besideObj);
        } catch (const Error& e) {
            obj.fail(e.what(), e.kind());
        }
        if (meshes.empty()) obj.fail(detail::quote(written) + " has no faces");
        return meshes;
    }

    // Keyframes must be in time order: the interpolation in scene.cpp searches them.
    template <class Key, class ReadKey>
    static std::vector<Key> keyframes(const JsonValue& list, ReadKey readKey) {
        std::vector<Key> keys;
        for (std::size_t i = 0; i < list.arraySize(); ++i) {
            const JsonValue item = list[i];
            Key k = readKey(item);
            if (!keys.empty() && k.time < keys.back().time)
                core::failAt(item.source(), core::jsonChildPath(item.path(), "time"),
                             "keys must be in time order (" + std::to_string(k.time) + " comes after " +
                                 std::to_string(keys.back().time) + ")");
            keys.push_back(k);
        }
        return keys;
    }

    static std::vector<Keyframe> motion(const JsonValue& v) {
        return keyframes<Keyframe>(v, [](const JsonValue& k) {
            JsonObject o(k);
            o.only({"time", "translation", "rotationYDegrees"});
            Keyframe key;
            key.time = o.require("time").number();
            if (auto t = o.get("translation")) key.translation = vec3(*t);
            if (auto r = o.get("rotationYDegrees")) key.rotationYDegrees = r->number();
            return key;
        });
    }

    static Sun sun(const JsonValue& v) {
        JsonObject o(v);
        o.only({"direction", "radiance", "angularRadiusDegrees", "motion"});
        Sun s;
        if (auto d = o.get("direction")) s.direction = direction(*d);
        if (auto r = o.get("radiance")) s.radiance = colour(*r);
        if (auto a = o.get("angularRadiusDegrees")) {
            s.angularRadiusDegrees = a->nonNegative();
            if (s.angularRadiusDegrees >= 90.0f) a->fail("must be below 90 degrees");
        }
        if (auto m = o.get("motion")) s.motion = motion(*m);
        return s;
    }

    static Sky sky(const JsonValue& v) {
        JsonObject o(v);
        o.only({"zenith", "horizon", "ground"});
        Sky s;
        if (auto c = o.get("zenith")) s.zenith = colour(*c);
        if (auto c = o.get("horizon")) s.horizon = colour(*c);
        if (auto c = o.get("ground")) s.ground = colour(*c);
        return s;
    }

    static CameraPath camera(const JsonValue& v) {
        JsonObject o(v);
        o.only({"name", "keys", "near", "far"});
        CameraPath c;
        const auto name = o.get("name");
        c.name = name ? name->string() : std::string("camera");
        if (auto n = o.get("near")) c.nearPlane = n->positive();
        if (auto f = o.get("far")) c.farPlane = f->positive();
        if (!(c.farPlane > c.nearPlane))
            v.fail("far (" + std::to_string(c.farPlane) + ") must be greater than near (" + std::to_string(c.nearPlane) +
                   ")");
        const JsonValue keys = o.require("keys");
        c.keys = keyframes<CameraKey>(keys, cameraKey);
        if (c.keys.empty()) keys.fail("needs at least one key");
        return c;
    }

    static CameraKey cameraKey(const JsonValue& v) {
        JsonObject o(v);
        o.only({"time", "position", "target", "up", "fov"});
        CameraKey key;
        if (auto t = o.get("time")) key.time = t->number();
        for (const char* required : {"position", "target"})
            if (!o.has(required)) v.fail(std::string("missing field '") + required + "'");
        key.position = vec3(o.require("position"));
        key.target = vec3(o.require("target"));
        const auto up = o.get("up");
        if (up) key.up = direction(*up);
        if (auto fov = o.get("fov")) {
            key.verticalFovDegrees = fov->number();
            if (!(key.verticalFovDegrees > 0.0f && key.verticalFovDegrees < 180.0f))
                fov->fail("vertical field of view must be in (0, 180) degrees");
        }
        // A view direction and an up vector along it leave the camera's roll undefined.
        const glm::dvec3 view = glm::dvec3(key.target) - glm::dvec3(key.position);
        if (!(glm::length(view) > 0.0)) v.fail("position and target must differ");
        if (!(glm::length(glm::cross(glm::normalize(view), glm::dvec3(key.up))) > 1e-6))
            core::failAt(v.source(), core::jsonChildPath(v.path(), "up"),
                         "must not be parallel to the view direction (target - position)");
        return key;
    }

    const FileReader& readFile_;
    std::map<std::string, std::string> materialPaths_;
};

} // namespace

Scene parseSceneFile(std::string_view text, const std::string& name, const FileReader& readFile) {
    const core::Json root = core::parseJson(text, name);
    Scene scene = SceneReader(readFile).read(JsonValue(root, name, ""));
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
