// The external Cornell box of ../shared/scenes/cbox: meshes, triangle counts and
// bounds checked against the files themselves (read here with a separate, minimal
// reader), and the README's materials, light and camera.
#include <array>
#include <fstream>
#include <limits>
#include <sstream>

#include <catch2/catch.hpp>

#include <hush/core/error.hpp>
#include <hush/tracer/scene_file.hpp>

using namespace hush::tracer;

namespace {

const std::string kFolder = HUSH_SHARED_DIR "/scenes/cbox";

struct Expected {
    std::size_t triangles = 0;
    glm::vec3 lo{std::numeric_limits<float>::max()};
    glm::vec3 hi{std::numeric_limits<float>::lowest()};
};

// Counts each 'f' line's polygon as (corners - 2) triangles and bounds the vertices
// faces use. The cbox files only use positive indices, which keeps this reader small.
Expected expectedFor(const std::string& file) {
    std::ifstream in(kFolder + "/" + file + ".obj");
    REQUIRE(in);
    std::vector<glm::vec3> v;
    Expected e;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string keyword;
        s >> keyword;
        if (keyword == "v") {
            glm::vec3 p;
            s >> p.x >> p.y >> p.z;
            v.push_back(p);
        } else if (keyword == "f") {
            std::size_t corners = 0;
            for (std::string corner; s >> corner; ++corners) {
                const glm::vec3 p = v.at(std::stoul(corner.substr(0, corner.find('/'))) - 1);
                e.lo = glm::min(e.lo, p);
                e.hi = glm::max(e.hi, p);
            }
            e.triangles += corners - 2;
        }
    }
    return e;
}

const Mesh& meshNamed(const Scene& scene, const std::string& name) {
    for (const Mesh& m : scene.meshes)
        if (m.name == name) return m;
    FAIL("no mesh " << name);
    throw;
}

} // namespace

TEST_CASE("obj: the external Cornell box loads with the files' meshes and the README's facts", "[obj][cbox]") {
    const Scene scene = loadCornellBoxObj(kFolder);
    CHECK(scene.name == "cbox");
    CHECK(scene.sceneScale == 0.001f);
    REQUIRE(scene.meshes.size() == 8);

    const std::array<const char*, 8> files = {"cbox_floor",    "cbox_ceiling",  "cbox_back",     "cbox_redwall",
                                              "cbox_greenwall", "cbox_smallbox", "cbox_largebox", "cbox_luminaire"};
    std::size_t total = 0;
    for (const char* file : files) {
        INFO(file);
        const Mesh& m = meshNamed(scene, file);
        Expected e = expectedFor(file);
        if (std::string(file) == "cbox_luminaire") {
            e.lo.y -= 0.5f;   // the README moves it down
            e.hi.y -= 0.5f;
        }
        CHECK(m.triangles.size() == e.triangles);
        total += m.triangles.size();
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
        for (const glm::vec3& p : m.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        for (int c = 0; c < 3; ++c) {
            CHECK(lo[c] == Approx(e.lo[c]));
            CHECK(hi[c] == Approx(e.hi[c]));
        }
        CHECK(m.motion.empty());
    }
    // 2 per wall quad, 4 for the ceiling with its hole, 12 per box.
    CHECK(total == 2 + 4 + 2 + 2 + 2 + 12 + 12 + 2);
    // The floor's hole vertices are unused: only its 4 corners are kept.
    CHECK(meshNamed(scene, "cbox_floor").positions.size() == 4);
    // The boxes carry per-vertex normals (v//vn), the walls do not.
    CHECK(meshNamed(scene, "cbox_largebox").normals.size() == meshNamed(scene, "cbox_largebox").positions.size());
    CHECK(meshNamed(scene, "cbox_back").normals.empty());
    CHECK(meshNamed(scene, "cbox_luminaire").positions[0].y == Approx(548.3f));

    auto materialOf = [&](const char* mesh) { return scene.materials.at(meshNamed(scene, mesh).material); };
    CHECK(materialOf("cbox_floor").albedo == glm::vec3(0.885809f, 0.698859f, 0.666422f));
    CHECK(materialOf("cbox_ceiling").name == "white");
    CHECK(materialOf("cbox_back").name == "white");
    CHECK(materialOf("cbox_redwall").albedo == glm::vec3(0.570068f, 0.0430135f, 0.0443706f));
    CHECK(materialOf("cbox_greenwall").albedo == glm::vec3(0.105421f, 0.37798f, 0.076425f));
    CHECK(materialOf("cbox_smallbox").albedo == glm::vec3(0.45f, 0.30f, 0.90f));
    CHECK(materialOf("cbox_largebox").name == "box");
    const Material light = materialOf("cbox_luminaire");
    CHECK(light.albedo == glm::vec3(0.936461f, 0.740433f, 0.705267f));
    CHECK(light.emission == glm::vec3(18.387f, 10.9873f, 2.75357f));
    int emitters = 0;
    for (const Material& m : scene.materials) emitters += m.emission != glm::vec3(0.0f);
    CHECK(emitters == 1);
    for (const Material& m : scene.materials) CHECK(m.specular == glm::vec3(0.0f));

    CHECK(scene.camera.name == "cbox");
    REQUIRE(scene.camera.keys.size() == 1);
    const CameraKey& k = scene.camera.keys[0];
    CHECK(k.position == glm::vec3(278, 273, -800));
    CHECK(k.target == glm::vec3(278, 273, -799));
    CHECK(k.up == glm::vec3(0, 1, 0));
    CHECK(k.verticalFovDegrees == Approx(39.3077f));
    CHECK(scene.camera.nearPlane == 10.0f);
    CHECK(scene.camera.farPlane == 2800.0f);
    CHECK_NOTHROW(scene.validate());
}

TEST_CASE("obj: the Cornell box loader names a missing folder", "[obj][cbox]") {
    try {
        loadCornellBoxObj("/nonexistent/cbox");
        FAIL("no error");
    } catch (const hush::Error& e) {
        CHECK(e.kind() == hush::ErrorKind::NotFound);
        CHECK_THAT(e.what(), Catch::Contains("/nonexistent/cbox/cbox_floor.obj"));
    }
}
