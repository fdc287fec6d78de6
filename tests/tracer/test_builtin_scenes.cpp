// The built-in scenes: valid, deterministic, and what docs/scenes.md says they are
// (the Cornell box against the external reference meshes and README).
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include <hush/core/error.hpp>
#include <hush/tracer/builtin_scenes.hpp>

using namespace hush::tracer;

namespace {

const std::vector<std::string> kExpectedNames = {"cornell", "room", "glossy", "moving-light", "thin"};

struct Bounds {
    glm::vec3 lo{std::numeric_limits<float>::max()};
    glm::vec3 hi{std::numeric_limits<float>::lowest()};
    void add(glm::vec3 p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
};

Bounds worldBounds(const Mesh& mesh, float time) {
    Bounds b;
    const glm::mat4 m = mesh.transformAt(time);
    for (const auto& p : mesh.positions) b.add(glm::vec3(m * glm::vec4(p, 1.0f)));
    return b;
}

// The 'v' lines of one reference OBJ: the expected dimensions come from the
// external files themselves, not from numbers copied into this test.
Bounds objVertexBounds(const std::string& file) {
    std::ifstream in(std::string(HUSH_SHARED_DIR) + "/scenes/cbox/" + file);
    REQUIRE(in.good());
    Bounds b;
    std::string line;
    int count = 0;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        std::string tag;
        glm::vec3 p;
        if (ls >> tag && tag == "v" && ls >> p.x >> p.y >> p.z) {
            b.add(p);
            ++count;
        }
    }
    REQUIRE(count >= 4);
    return b;
}

const Mesh& meshNamed(const Scene& scene, const std::string& name) {
    const auto it = std::find_if(scene.meshes.begin(), scene.meshes.end(), [&](const Mesh& m) { return m.name == name; });
    REQUIRE(it != scene.meshes.end());
    return *it;
}

size_t triangleCount(const Scene& scene) {
    size_t n = 0;
    for (const auto& m : scene.meshes) n += m.triangles.size();
    return n;
}

bool emissive(const Material& m) { return glm::any(glm::greaterThan(m.emission, glm::vec3(0.0f))); }

bool sameKey(const CameraKey& a, const CameraKey& b) {
    return a.time == b.time && a.position == b.position && a.target == b.target && a.up == b.up &&
           a.verticalFovDegrees == b.verticalFovDegrees;
}

bool sameFrame(const Keyframe& a, const Keyframe& b) {
    return a.time == b.time && a.translation == b.translation && a.rotationYDegrees == b.rotationYDegrees;
}

// Bit-for-bit equality of everything a renderer reads.
bool identical(const Scene& a, const Scene& b) {
    if (a.name != b.name || a.framesPerSecond != b.framesPerSecond || a.sceneScale != b.sceneScale) return false;
    if (a.materials.size() != b.materials.size() || a.meshes.size() != b.meshes.size()) return false;
    for (size_t i = 0; i < a.materials.size(); ++i) {
        const auto &x = a.materials[i], &y = b.materials[i];
        if (x.name != y.name || x.albedo != y.albedo || x.specular != y.specular || x.roughness != y.roughness ||
            x.emission != y.emission)
            return false;
    }
    for (size_t i = 0; i < a.meshes.size(); ++i) {
        const auto &x = a.meshes[i], &y = b.meshes[i];
        if (x.name != y.name || x.positions != y.positions || x.normals != y.normals || x.triangles != y.triangles ||
            x.material != y.material || x.motion.size() != y.motion.size())
            return false;
        for (size_t k = 0; k < x.motion.size(); ++k)
            if (!sameFrame(x.motion[k], y.motion[k])) return false;
    }
    if (a.sun.direction != b.sun.direction || a.sun.radiance != b.sun.radiance ||
        a.sun.angularRadiusDegrees != b.sun.angularRadiusDegrees || a.sun.motion.size() != b.sun.motion.size())
        return false;
    if (a.sky.zenith != b.sky.zenith || a.sky.horizon != b.sky.horizon || a.sky.ground != b.sky.ground) return false;
    if (a.camera.name != b.camera.name || a.camera.nearPlane != b.camera.nearPlane ||
        a.camera.farPlane != b.camera.farPlane || a.camera.keys.size() != b.camera.keys.size())
        return false;
    for (size_t k = 0; k < a.camera.keys.size(); ++k)
        if (!sameKey(a.camera.keys[k], b.camera.keys[k])) return false;
    return true;
}

// Möller-Trumbore, both sides: does the segment origin + t dir, t in (eps, tMax), hit the scene?
bool occluded(const Scene& scene, glm::vec3 origin, glm::vec3 dir, float tMax) {
    for (const auto& mesh : scene.meshes) {
        const glm::mat4 m = mesh.transformAt(0.0f);
        for (const auto& tri : mesh.triangles) {
            const glm::vec3 a(m * glm::vec4(mesh.positions[tri.x], 1.0f));
            const glm::vec3 e1 = glm::vec3(m * glm::vec4(mesh.positions[tri.y], 1.0f)) - a;
            const glm::vec3 e2 = glm::vec3(m * glm::vec4(mesh.positions[tri.z], 1.0f)) - a;
            const glm::vec3 p = glm::cross(dir, e2);
            const float det = glm::dot(e1, p);
            if (std::abs(det) < 1e-12f) continue;
            const glm::vec3 s = origin - a;
            const float u = glm::dot(s, p) / det;
            const glm::vec3 q = glm::cross(s, e1);
            const float v = glm::dot(dir, q) / det;
            const float t = glm::dot(e2, q) / det;
            if (u >= 0.0f && v >= 0.0f && u + v <= 1.0f && t > 1e-4f && t < tMax) return true;
        }
    }
    return false;
}

} // namespace

TEST_CASE("built-in scenes: names round-trip in the documented order", "[tracer][scenes]") {
    CHECK(builtinSceneNames() == kExpectedNames);
    CHECK(defaultSceneName() == "cornell");
    for (const auto& name : builtinSceneNames()) CHECK(makeBuiltinScene(name).name == name);
}

TEST_CASE("built-in scenes: an unknown name is an error listing the names", "[tracer][scenes]") {
    try {
        (void)makeBuiltinScene("sponza");
        FAIL("no error for an unknown scene");
    } catch (const hush::Error& e) {
        const std::string message = e.what();
        CHECK(message.find("sponza") != std::string::npos);
        for (const auto& name : kExpectedNames) CHECK(message.find(name) != std::string::npos);
    }
}

TEST_CASE("built-in scenes: every one is valid, finite, lit and animated", "[tracer][scenes]") {
    for (const auto& name : builtinSceneNames()) {
        INFO("scene " << name);
        const Scene scene = makeBuiltinScene(name);
        REQUIRE_NOTHROW(scene.validate());
        CHECK(scene.framesPerSecond == 30.0f);
        CHECK(scene.sceneScale > 0.0f);
        CHECK_FALSE(scene.camera.name.empty());
        CHECK(scene.camera.nearPlane > 0.0f);
        CHECK(scene.camera.farPlane > scene.camera.nearPlane);
        REQUIRE(scene.camera.keys.size() >= 2);
        CHECK(std::is_sorted(scene.camera.keys.begin(), scene.camera.keys.end(),
                             [](const CameraKey& a, const CameraKey& b) { return a.time < b.time; }));
        CHECK(scene.camera.keys.front().time == 0.0f);
        CHECK(scene.camera.keys.back().time >= 2.0f);   // "a few seconds"
        CHECK(triangleCount(scene) < 100000);

        for (const auto& mesh : scene.meshes) {
            INFO("mesh " << mesh.name);
            REQUIRE(mesh.normals.size() == mesh.positions.size());
            for (size_t i = 0; i < mesh.positions.size(); ++i) {
                const glm::vec3 p = mesh.positions[i], n = mesh.normals[i];
                REQUIRE((std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)));
                REQUIRE(std::abs(glm::length(n) - 1.0f) < 1e-4f);
            }
            // Winding and normals agree: the builders' faces point where their normals do.
            for (const auto& t : mesh.triangles) {
                const glm::vec3 face = glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                                  mesh.positions[t.z] - mesh.positions[t.x]);
                REQUIRE(glm::length(face) > 0.0f);
                REQUIRE(glm::dot(face, mesh.normals[t.x] + mesh.normals[t.y] + mesh.normals[t.z]) > 0.0f);
            }
        }
        // Every light sits on geometry, and every scene has some light.
        bool lit = glm::any(glm::greaterThan(scene.sun.radiance, glm::vec3(0.0f))) ||
                   glm::any(glm::greaterThan(scene.sky.zenith + scene.sky.horizon, glm::vec3(0.0f)));
        for (uint32_t i = 0; i < scene.materials.size(); ++i) {
            const auto& material = scene.materials[i];
            INFO("material " << material.name);
            CHECK(glm::all(glm::lessThanEqual(material.albedo, glm::vec3(0.95f))));
            if (!emissive(material)) continue;
            lit = true;
            CHECK(std::any_of(scene.meshes.begin(), scene.meshes.end(), [&](const Mesh& m) { return m.material == i; }));
        }
        CHECK(lit);
    }
}

TEST_CASE("built-in scenes: two calls give identical scenes", "[tracer][scenes]") {
    for (const auto& name : builtinSceneNames()) {
        INFO("scene " << name);
        CHECK(identical(makeBuiltinScene(name), makeBuiltinScene(name)));
    }
}

TEST_CASE("built-in scenes: cornell matches the reference meshes and camera", "[tracer][scenes][cornell]") {
    const Scene scene = makeBuiltinScene("cornell");
    CHECK(scene.sceneScale == 0.001f);

    // Each mesh spans what its reference OBJ spans; the luminaire 0.5 mm lower.
    const std::pair<const char*, float> meshes[] = {
        {"cbox_floor", 0.0f},    {"cbox_ceiling", 0.0f},  {"cbox_back", 0.0f},     {"cbox_greenwall", 0.0f},
        {"cbox_redwall", 0.0f},  {"cbox_smallbox", 0.0f}, {"cbox_largebox", 0.0f}, {"cbox_luminaire", -0.5f}};
    Bounds all, expectedAll;
    for (const auto& [name, dy] : meshes) {
        INFO("mesh " << name);
        Bounds expected = objVertexBounds(std::string(name) + ".obj");
        expectedAll.add(expected.lo);
        expectedAll.add(expected.hi);
        expected.lo.y += dy;
        expected.hi.y += dy;
        const Bounds got = worldBounds(meshNamed(scene, name), 0.0f);
        all.add(got.lo);
        all.add(got.hi);
        for (int k = 0; k < 3; ++k) {
            CHECK(got.lo[k] == Approx(expected.lo[k]).margin(1e-3));
            CHECK(got.hi[k] == Approx(expected.hi[k]).margin(1e-3));
        }
    }
    CHECK(scene.meshes.size() == std::size(meshes));
    for (int k = 0; k < 3; ++k) {
        CHECK(all.lo[k] == Approx(expectedAll.lo[k]).margin(1e-3));
        CHECK(all.hi[k] == Approx(expectedAll.hi[k]).margin(1e-3));
    }

    // The README's camera, exactly, at key 0 of "dolly-pan".
    CHECK(scene.camera.name == "dolly-pan");
    const CameraKey& k0 = scene.camera.keys.front();
    CHECK(k0.position == glm::vec3(278.0f, 273.0f, -800.0f));
    CHECK(k0.target == glm::vec3(278.0f, 273.0f, -799.0f));
    CHECK(k0.up == glm::vec3(0.0f, 1.0f, 0.0f));
    CHECK(k0.verticalFovDegrees == 39.3077f);
    CHECK(scene.camera.nearPlane == 10.0f);
    CHECK(scene.camera.farPlane == 2800.0f);
    CHECK(scene.camera.keys.back().time == Approx(2.0f));
    CHECK(scene.camera.keys.back().position != k0.position);

    // The README's emitter, on the luminaire only.
    const Mesh& luminaire = meshNamed(scene, "cbox_luminaire");
    CHECK(scene.materials[luminaire.material].emission == glm::vec3(18.387f, 10.9873f, 2.75357f));
    CHECK(scene.materials[meshNamed(scene, "cbox_redwall").material].albedo ==
          glm::vec3(0.570068f, 0.0430135f, 0.0443706f));
    for (const auto& mesh : scene.meshes)
        if (mesh.name != "cbox_luminaire") CHECK_FALSE(emissive(scene.materials[mesh.material]));
}

TEST_CASE("built-in scenes: moving-light has a static camera and a moving light", "[tracer][scenes]") {
    const Scene scene = makeBuiltinScene("moving-light");
    const auto& keys = scene.camera.keys;
    for (const auto& k : keys) {
        CHECK(k.position == keys.front().position);
        CHECK(k.target == keys.front().target);
        CHECK(k.up == keys.front().up);
        CHECK(k.verticalFovDegrees == keys.front().verticalFovDegrees);
    }
    int movingLights = 0;
    for (const auto& mesh : scene.meshes) {
        if (!emissive(scene.materials[mesh.material])) continue;
        const glm::mat4 first = mesh.transformAt(0.0f), last = mesh.transformAt(keys.back().time);
        const glm::mat4 middle = mesh.transformAt(0.5f * keys.back().time);
        if (first != last && first != middle) ++movingLights;
    }
    CHECK(movingLights == 1);
}

TEST_CASE("built-in scenes: glossy has every listed GGX roughness and a perfect mirror", "[tracer][scenes]") {
    const Scene scene = makeBuiltinScene("glossy");
    for (const float alpha : {0.02f, 0.05f, 0.1f, 0.2f, 0.4f, 0.8f}) {
        INFO("alpha " << alpha);
        CHECK(std::any_of(scene.materials.begin(), scene.materials.end(), [&](const Material& m) {
            return m.roughness == alpha && glm::any(glm::greaterThan(m.specular, glm::vec3(0.0f)));
        }));
    }
    CHECK(std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) {
        return m.roughness == 0.0f && glm::all(glm::greaterThan(m.specular, glm::vec3(0.9f)));
    }));

    // The spheres are closed and consistently wound: every directed edge once,
    // its reverse once (no holes in what reflections and shadows see).
    for (const auto& mesh : scene.meshes) {
        if (mesh.name.find("sphere") == std::string::npos) continue;
        INFO("mesh " << mesh.name);
        std::map<std::pair<uint32_t, uint32_t>, int> edges;
        for (const auto& t : mesh.triangles)
            for (const auto& e : {std::pair(t.x, t.y), std::pair(t.y, t.z), std::pair(t.z, t.x)}) ++edges[e];
        for (const auto& [e, count] : edges) {
            REQUIRE(count == 1);
            REQUIRE(edges.count({e.second, e.first}) == 1);
        }
    }
}

TEST_CASE("built-in scenes: thin has thousands of thin triangles", "[tracer][scenes]") {
    CHECK(triangleCount(makeBuiltinScene("thin")) > 1000);
}

TEST_CASE("built-in scenes: room lets the sun onto the floor through the window only", "[tracer][scenes]") {
    const Scene scene = makeBuiltinScene("room");
    REQUIRE(glm::any(glm::greaterThan(scene.sun.radiance, glm::vec3(0.0f))));
    const glm::vec3 toSun = -glm::normalize(scene.sun.direction);
    // Inside the patch the window lets the sun through; elsewhere the room's walls
    // and ceiling block it, so most of the room is lit indirectly.
    CHECK_FALSE(occluded(scene, {-1.4f, 0.02f, 0.2f}, toSun, 100.0f));
    CHECK(occluded(scene, {1.5f, 0.02f, 1.0f}, toSun, 100.0f));
    CHECK(occluded(scene, {-1.4f, 0.02f, -2.2f}, toSun, 100.0f));
    CHECK(occluded(scene, {0.0f, 1.5f, 0.0f}, glm::vec3(0.0f, 1.0f, 0.0f), 100.0f));   // closed above
}
