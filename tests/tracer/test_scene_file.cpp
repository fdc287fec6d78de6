// The JSON scene file: the complete example of docs/scene-format.md, exact round
// trips through writeSceneFile, and errors with their JSON path or line:column.
#include <fstream>
#include <sstream>

#include <catch2/catch.hpp>

#include <hush/core/error.hpp>
#include <hush/tracer/scene_file.hpp>

using namespace hush::tracer;

namespace {

const std::string kScenes = HUSH_TEST_DATA_DIR "/scenes";

// The first ```json block of docs/scene-format.md: the documented example must load.
std::string docsExample() {
    std::ifstream in(HUSH_TEST_DATA_DIR "/../../../docs/scene-format.md");
    REQUIRE(in);
    std::stringstream s;
    s << in.rdbuf();
    const std::string doc = s.str();
    const std::size_t begin = doc.find("```json\n");
    REQUIRE(begin != std::string::npos);
    const std::size_t end = doc.find("\n```", begin + 8);
    REQUIRE(end != std::string::npos);
    return doc.substr(begin + 8, end - begin - 8);
}

std::string errorOf(const std::string& text, const FileReader& reader = {}) {
    try {
        parseSceneFile(text, "scene.json", reader);
    } catch (const hush::Error& e) {
        return e.what();
    }
    return "(no error)";
}

const std::string kCamera = R"("camera": {"keys": [{"position": [0, 0, 5], "target": [0, 0, 0]}]})";
const std::string kTriangle = R"({"material": "m", "positions": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]]})";

// A valid scene with one field replaced: `materials`, `meshes` and `camera` parts.
std::string scene(const std::string& meshes, const std::string& extra = "", const std::string& camera = kCamera) {
    return R"({"materials": [{"name": "m"}], "meshes": [)" + meshes + "], " + camera + extra + "}";
}

void requireSame(const Scene& a, const Scene& b) {
    CHECK(a.name == b.name);
    CHECK(a.framesPerSecond == b.framesPerSecond);
    CHECK(a.sceneScale == b.sceneScale);
    REQUIRE(a.materials.size() == b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        CHECK(a.materials[i].name == b.materials[i].name);
        CHECK(a.materials[i].albedo == b.materials[i].albedo);
        CHECK(a.materials[i].specular == b.materials[i].specular);
        CHECK(a.materials[i].roughness == b.materials[i].roughness);
        CHECK(a.materials[i].emission == b.materials[i].emission);
        CHECK(a.materials[i].doubleSidedEmission == b.materials[i].doubleSidedEmission);
    }
    REQUIRE(a.meshes.size() == b.meshes.size());
    for (std::size_t i = 0; i < a.meshes.size(); ++i) {
        const Mesh& x = a.meshes[i];
        const Mesh& y = b.meshes[i];
        CHECK(x.name == y.name);
        CHECK(x.material == y.material);
        CHECK(x.positions == y.positions);
        CHECK(x.normals == y.normals);
        CHECK(x.triangles == y.triangles);
        REQUIRE(x.motion.size() == y.motion.size());
        for (std::size_t k = 0; k < x.motion.size(); ++k) {
            CHECK(x.motion[k].time == y.motion[k].time);
            CHECK(x.motion[k].translation == y.motion[k].translation);
            CHECK(x.motion[k].rotationYDegrees == y.motion[k].rotationYDegrees);
        }
    }
    CHECK(a.sun.direction == b.sun.direction);
    CHECK(a.sun.radiance == b.sun.radiance);
    CHECK(a.sun.angularRadiusDegrees == b.sun.angularRadiusDegrees);
    CHECK(a.sun.motion.size() == b.sun.motion.size());
    CHECK(a.sky.zenith == b.sky.zenith);
    CHECK(a.sky.horizon == b.sky.horizon);
    CHECK(a.sky.ground == b.sky.ground);
    CHECK(a.camera.name == b.camera.name);
    CHECK(a.camera.nearPlane == b.camera.nearPlane);
    CHECK(a.camera.farPlane == b.camera.farPlane);
    REQUIRE(a.camera.keys.size() == b.camera.keys.size());
    for (std::size_t k = 0; k < a.camera.keys.size(); ++k) {
        CHECK(a.camera.keys[k].time == b.camera.keys[k].time);
        CHECK(a.camera.keys[k].position == b.camera.keys[k].position);
        CHECK(a.camera.keys[k].target == b.camera.keys[k].target);
        CHECK(a.camera.keys[k].up == b.camera.keys[k].up);
        CHECK(a.camera.keys[k].verticalFovDegrees == b.camera.keys[k].verticalFovDegrees);
    }
}

} // namespace

TEST_CASE("scene file: the documented example loads as described", "[scene]") {
    const Scene s = parseSceneFile(docsExample(), "docs/example.json", folderReader(kScenes));
    CHECK(s.name == "example");
    CHECK(s.framesPerSecond == 30.0f);
    REQUIRE(s.materials.size() == 4);
    CHECK(s.materials[3].name == "grey");   // appended from quad.mtl
    CHECK(s.materials[3].roughness == Approx(0.1f));
    REQUIRE(s.meshes.size() == 5);
    const char* names[] = {"floor", "lamp", "plain/floor", "plain/lamp", "spinner"};
    const char* materials[] = {"grey", "lamp", "white", "white", "gold"};
    for (std::size_t i = 0; i < 5; ++i) {
        CHECK(s.meshes[i].name == names[i]);
        CHECK(s.materials[s.meshes[i].material].name == materials[i]);
    }
    // The JSON "lamp" wins over quad.mtl's.
    CHECK(s.materials[s.meshes[1].material].emission == glm::vec3(20, 18, 15));
    const Mesh& spinner = s.meshes[4];
    REQUIRE(spinner.motion.size() == 2);
    CHECK(spinner.motion[1].rotationYDegrees == 180.0f);
    CHECK(spinner.normals.size() == 3);
    CHECK(glm::length(s.sun.direction) == Approx(1.0f));
    CHECK(s.sun.radiance == glm::vec3(40, 38, 35));
    CHECK(s.sky.zenith == glm::vec3(0.2f, 0.35f, 0.8f));
    CHECK(s.camera.name == "dolly");
    REQUIRE(s.camera.keys.size() == 2);
    CHECK(s.camera.keys[1].up == glm::vec3(0, 1, 0));   // the default
    CHECK(s.camera.keys[1].verticalFovDegrees == 40.0f);
    CHECK(s.camera.nearPlane == 0.05f);
}

TEST_CASE("scene file: loadSceneFile resolves obj paths beside the scene file", "[scene]") {
    const std::string path = kScenes + "/two_quads.json";
    const Scene s = loadSceneFile(path);
    CHECK(s.name == "two_quads");   // no "name": the file's stem
    REQUIRE(s.meshes.size() == 2);
    CHECK(s.materials[s.meshes[1].material].emission == glm::vec3(10.0f));
    try {
        loadSceneFile(kScenes + "/missing.json");
        FAIL("no error");
    } catch (const hush::Error& e) {
        CHECK(e.kind() == hush::ErrorKind::NotFound);
        CHECK_THAT(e.what(), Catch::Contains("missing.json"));
    }
}

TEST_CASE("scene file: write then parse is an exact round trip", "[scene]") {
    const Scene original = parseSceneFile(docsExample(), "example.json", folderReader(kScenes));
    const std::string text = writeSceneFile(original);
    const Scene back = parseSceneFile(text, "written.json");
    requireSame(original, back);
    CHECK(writeSceneFile(back) == text);

    // The Cornell box too (no sun, one emitter, millimetres).
    const Scene cbox = loadCornellBoxObj(HUSH_SHARED_DIR "/scenes/cbox");
    requireSame(cbox, parseSceneFile(writeSceneFile(cbox), "cbox.json"));

    Scene twoSided = original;
    twoSided.materials[2].doubleSidedEmission = true;
    requireSame(twoSided, parseSceneFile(writeSceneFile(twoSided), "two-sided.json"));

    Scene duplicate = original;
    duplicate.materials[1].name = duplicate.materials[0].name;
    CHECK_THROWS_WITH(writeSceneFile(duplicate), Catch::Contains("repeated material name 'white'"));
}

TEST_CASE("scene file: errors name the file and the JSON path", "[scene]") {
    struct Case {
        std::string text;
        std::string message;
    };
    const Case cases[] = {
        {scene(kTriangle + R"(, {"material": "m", "positions": [[0,0,0]], "triangles": [[0,0,0]]},
                {"material": "gold", "positions": [[0,0,0]], "triangles": [[0,0,0]]})"),
         "scene.json: meshes[2].material: unknown material 'gold'"},
        {scene(kTriangle, R"(, "extra": 1)"),
         "scene.json: unknown field 'extra' (known fields: name, framesPerSecond, sceneScale, materials, meshes, sun, sky, camera)"},
        {R"({"materials": [{"name": "m", "albdeo": [1, 1, 1]}], "meshes": [)" + kTriangle + "], " + kCamera + "}",
         "scene.json: materials[0]: unknown field 'albdeo' (known fields: name, albedo, specular, roughness, emission, doubleSidedEmission)"},
        {R"({"materials": [{"name": "m"}, {"name": "m"}], "meshes": [)" + kTriangle + "], " + kCamera + "}",
         "scene.json: materials[1].name: 'm' is already defined by materials[0]"},
        {R"({"materials": [{"name": "m", "albedo": [1, -1, 1]}], "meshes": [)" + kTriangle + "], " + kCamera + "}",
         "scene.json: materials[0].albedo[1]: must be >= 0, got -1.000000"},
        {R"({"materials": [{"name": "m", "roughness": "low"}], "meshes": [)" + kTriangle + "], " + kCamera + "}",
         "scene.json: materials[0].roughness: must be a number"},
        {R"({"meshes": [], )" + kCamera + "}", "scene.json: meshes: needs at least one mesh"},
        {"{" + kCamera + "}", "scene.json: missing field 'meshes'"},
        {scene(kTriangle, "", R"("cam": 1)"), "scene.json: unknown field 'cam' (known fields: name, framesPerSecond, sceneScale, materials, meshes, sun, sky, camera)"},
        {R"({"materials": [{"name": "m"}], "meshes": [)" + kTriangle + "]}", "scene.json: missing field 'camera'"},
        {"[1, 2]", "scene.json: (top level): must be a JSON object"},
        {R"({"materials": [{"name": "m", "doubleSidedEmission": 1}], "meshes": [)" + kTriangle + "], " + kCamera + "}",
         "scene.json: materials[0].doubleSidedEmission: must be true or false"},
        {scene(R"({"material": "m", "positions": [[0,0,0],[1,0]], "triangles": [[0,1,1]]})"),
         "scene.json: meshes[0].positions[1]: must be an array of 3 numbers"},
        {scene(R"({"material": "m", "positions": [[0,0,0],[1,0,0]], "triangles": [[0,1,2]]})"),
         "scene.json: meshes[0].triangles[0][2]: index 2 is past the 2 positions"},
        {scene(R"({"material": "m", "positions": [[0,0,0]], "triangles": [[0,-1,0]]})"),
         "scene.json: meshes[0].triangles[0][1]: must be a non-negative integer"},
        {scene(R"({"material": "m", "positions": [[0,0,0]], "triangles": [[0,0.5,0]]})"),
         "scene.json: meshes[0].triangles[0][1]: must be a non-negative integer"},
        {scene(R"({"material": "m", "positions": [[0,0,0]], "triangles": []})"),
         "scene.json: meshes[0].triangles: needs at least one triangle"},
        {scene(R"({"material": "m", "positions": [[0,0,0]], "normals": [], "triangles": [[0,0,0]]})"),
         "scene.json: meshes[0].normals: has 0 normals for 1 positions (one per position)"},
        {scene(R"({"material": "m", "positions": [[0,0,0]], "normals": [[0,0,0]], "triangles": [[0,0,0]]})"),
         "scene.json: meshes[0].normals[0]: a normal needs a direction (zero length)"},
        {scene(R"({"material": "m", "positions": [[1e39,0,0]], "triangles": [[0,0,0]]})"),
         "scene.json: meshes[0].positions[0][0]: number out of range for a float"},
        {scene(R"({"material": "m"})"), "scene.json: meshes[0]: needs exactly one of 'obj' (a file) or 'positions' + 'triangles' (inline)"},
        {scene(R"({"obj": "a.obj", "positions": []})"), "scene.json: meshes[0]: needs exactly one of 'obj' (a file) or 'positions' + 'triangles' (inline)"},
        {scene(R"({"obj": "a.obj"})"), "scene.json: meshes[0].obj: no file access when parsing from memory"},
        {scene(R"({"obj": "a.obj", "material": "x"})"), "scene.json: meshes[0].material: unknown material 'x'"},
        {scene(kTriangle.substr(0, kTriangle.size() - 1) + R"(, "motion": [{"time": 1}, {"time": 0.5}]})"),
         "scene.json: meshes[0].motion[1].time: keys must be in time order (0.500000 comes after 1.000000)"},
        {scene(kTriangle.substr(0, kTriangle.size() - 1) + R"(, "motion": [{"translation": [1, 0, 0]}]})"),
         "scene.json: meshes[0].motion[0]: missing field 'time'"},
        {scene(kTriangle, R"(, "sun": {"direction": [0, 0, 0]})"), "scene.json: sun.direction: must not be zero"},
        {scene(kTriangle, R"(, "sun": {"angularRadiusDegrees": 90})"), "scene.json: sun.angularRadiusDegrees: must be below 90 degrees"},
        {scene(kTriangle, R"(, "sky": {"zenith": [1, 1]})"), "scene.json: sky.zenith: must be an RGB array of 3 numbers"},
        {scene(kTriangle, R"(, "framesPerSecond": 0)"), "scene.json: framesPerSecond: must be > 0, got 0.000000"},
        {scene(kTriangle, "", R"("camera": {"keys": []})"), "scene.json: camera.keys: needs at least one key"},
        {scene(kTriangle, "", R"("camera": {"near": 2, "far": 1, "keys": []})"),
         "scene.json: camera: far (1.000000) must be greater than near (2.000000)"},
        {scene(kTriangle, "", R"("camera": {"keys": [{"position": [0,0,0], "target": [0,0,0]}]})"),
         "scene.json: camera.keys[0]: position and target must differ"},
        {scene(kTriangle, "", R"("camera": {"keys": [{"position": [0,0,0], "target": [0,1,0]}]})"),
         "scene.json: camera.keys[0].up: must not be parallel to the view direction (target - position)"},
        {scene(kTriangle, "", R"("camera": {"keys": [{"position": [0,0,1], "target": [0,0,0], "fov": 180}]})"),
         "scene.json: camera.keys[0].fov: vertical field of view must be in (0, 180) degrees"},
        {scene(kTriangle, "", R"("camera": {"keys": [{"target": [0,0,0]}]})"), "scene.json: camera.keys[0]: missing field 'position'"},
        {scene(kTriangle, "", R"("camera": {"keys": [{"time": 2, "position": [0,0,1], "target": [0,0,0]}, {"time": 1, "position": [0,0,1], "target": [0,0,0]}]})"),
         "scene.json: camera.keys[1].time: keys must be in time order (1.000000 comes after 2.000000)"},
        {scene(kTriangle, R"(, "name": 5)"), "scene.json: name: must be a string"},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        CHECK(errorOf(c.text) == c.message);
    }
}

TEST_CASE("scene file: JSON syntax errors give line:column", "[scene]") {
    struct Case {
        std::string text;
        std::string prefix;
    };
    const Case cases[] = {
        {"", "scene.json:1:1: JSON syntax error: "},
        {"{\n  \"meshes\": [\n    {\"name\": 1,,}\n", "scene.json:3:16: JSON syntax error: "},
        {"{\r\n  \"a\": tru\r\n}", "scene.json:2:11: JSON syntax error: "},
        {"{\"a\": [1, 2]", "scene.json:1:13: JSON syntax error: "},
        {"{\"a\": \"\xff\"}", "scene.json:1:8: JSON syntax error: "},
        {"// comment\n/* block\n */ {\"a\" 1}", "scene.json:3:10: JSON syntax error: "},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        const std::string message = errorOf(c.text);
        CHECK_THAT(message, Catch::StartsWith(c.prefix));
        CHECK(message.find("[json.exception") == std::string::npos);   // nlohmann's prefix is replaced
    }
    CHECK_THAT(errorOf(scene(kTriangle, R"(, "sceneScale": 1e999)")),
               Catch::StartsWith("scene.json: JSON error: number overflow"));
}

TEST_CASE("scene file: errors inside an OBJ keep the OBJ's file:line", "[scene]") {
    const std::string text = scene(R"({"obj": "models/bad_face.obj"})");
    CHECK(errorOf(text, folderReader(kScenes)) ==
          "scene.json: meshes[0].obj: " + kScenes + "/models/bad_face.obj:3: face index 3 is past the 2 vertices defined so far");
    CHECK_THAT(errorOf(scene(R"({"obj": "models/missing_mtl.obj"})"), folderReader(kScenes)),
               Catch::Contains("meshes[0].obj: " + kScenes + "/models/missing_mtl.obj:1: mtllib 'missing.mtl': "));
    CHECK_THAT(errorOf(scene(R"({"obj": "nothing.obj"})"), folderReader(kScenes)),
               Catch::StartsWith("scene.json: meshes[0].obj: ") && Catch::Contains("nothing.obj: no such file"));
    // An OBJ without faces gives no mesh, which a scene cannot use.
    const FileReader onlyVertices = [](const std::string& name) { return FileText{name, "v 0 0 0\n"}; };
    CHECK(errorOf(scene(R"({"obj": "v.obj"})"), onlyVertices) == "scene.json: meshes[0].obj: 'v.obj' has no faces");
}
