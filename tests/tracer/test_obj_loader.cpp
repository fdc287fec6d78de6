// OBJ parsing: polygon kinds, indices, meshes per group and material, normals, line
// endings, and the named file:line error for each kind of malformed input.
#include <catch2/catch.hpp>

#include <hush/core/error.hpp>
#include <hush/tracer/obj_loader.hpp>

using namespace hush::tracer;

namespace {

std::vector<Mesh> parse(const std::string& text, std::vector<Material>& materials, const ObjOptions& options = {}) {
    return parseObj(text, "test.obj", materials, options);
}

std::vector<Mesh> parse(const std::string& text) {
    std::vector<Material> materials;
    return parse(text, materials);
}

std::string errorOf(const std::string& text, const ObjOptions& options = {}) {
    std::vector<Material> materials;
    try {
        parseObj(text, "bad.obj", materials, options);
    } catch (const hush::Error& e) {
        return e.what();
    }
    return "(no error)";
}

const std::string kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

} // namespace

TEST_CASE("obj: a triangle, with the default material and the file's name", "[obj]") {
    std::vector<Material> materials;
    const auto meshes = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "models/tri.obj", materials);
    REQUIRE(meshes.size() == 1);
    CHECK(meshes[0].name == "tri");
    CHECK(meshes[0].positions == std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    CHECK(meshes[0].triangles == std::vector<glm::uvec3>{{0, 1, 2}});
    CHECK(meshes[0].normals.empty());
    REQUIRE(materials.size() == 1);
    CHECK(materials[0].name == "default");
    CHECK(materials[0].albedo == glm::vec3(0.8f));
    CHECK(meshes[0].material == 0);
}

TEST_CASE("obj: every corner form and polygon size is fan-triangulated", "[obj]") {
    const std::string header = kSquare + "v 2 0 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5\nvn 0 0 1\n";
    const char* faces[] = {
        "f 1 2 3 4 5",
        "f 1/1 2/2 3/3 4/4 5/5",
        "f 1//1 2//1 3//1 4//1 5//1",
        "f 1/1/1 2/2/1 3/3/1 4/4/1 5/5/1",
    };
    for (const char* face : faces) {
        INFO(face);
        const auto meshes = parse(header + face + "\n");
        REQUIRE(meshes.size() == 1);
        // A pentagon gives the fan (0,1,2), (0,2,3), (0,3,4).
        CHECK(meshes[0].triangles == std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}});
        CHECK(meshes[0].positions.size() == 5);
        CHECK(meshes[0].normals.size() == (std::string(face).find("//") != std::string::npos ||
                                                   std::string(face).find("/1/") != std::string::npos
                                               ? 5u
                                               : 0u));
    }
}

TEST_CASE("obj: negative indices count back from the last element defined", "[obj]") {
    const auto meshes = parse(kSquare + "vn 0 0 2\nf -4//-1 -3//-1 -2//-1\nv 5 5 5\nf -1 -2 -3\n");
    REQUIRE(meshes.size() == 1);
    // The second face mixes in corners without normals, so the mesh has none.
    CHECK(meshes[0].normals.empty());
    CHECK(meshes[0].positions == std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {5, 5, 5}, {0, 1, 0}});
    CHECK(meshes[0].triangles == std::vector<glm::uvec3>{{0, 1, 2}, {3, 4, 2}});
}

TEST_CASE("obj: normals are normalized and split vertices", "[obj]") {
    const auto meshes = parse(kSquare + "vn 0 0 2\nvn 0 3 0\nf 1//1 2//1 3//1\nf 1//2 3//2 4//2\n");
    REQUIRE(meshes.size() == 1);
    const Mesh& m = meshes[0];
    // Vertices 1 and 3 appear with two normals each: 6 mesh vertices.
    REQUIRE(m.positions.size() == 6);
    REQUIRE(m.normals.size() == 6);
    CHECK(m.normals[0] == glm::vec3(0, 0, 1));
    CHECK(m.normals[3] == glm::vec3(0, 1, 0));
    CHECK(m.triangles == std::vector<glm::uvec3>{{0, 1, 2}, {3, 4, 5}});
}

TEST_CASE("obj: o, g and usemtl start named meshes, and unused vertices are dropped", "[obj]") {
    std::vector<Material> materials{Material{.name = "red"}, Material{.name = "blue"}};
    const std::string text = kSquare +
                             "v 9 9 9\n"        // used by no face
                             "o box\nusemtl red\nf 1 2 3\n"
                             "g lid\nf 1 3 4\nusemtl blue\nf 4 3 2\n"
                             "g\nusemtl red\nf 2 3 4\n"
                             "o empty\ng nothing\n"
                             "o box\ng lid\nusemtl red\nf 4 1 2\n";   // continues box/lid:red
    const auto meshes = parse(text, materials);
    REQUIRE(meshes.size() == 3);
    CHECK(meshes[0].name == "box");
    CHECK(meshes[0].material == 0);
    CHECK(meshes[0].triangles.size() == 2);   // f 1 2 3 and, after "g", f 2 3 4
    CHECK(meshes[1].name == "box/lid:red");
    CHECK(meshes[1].triangles.size() == 2);
    CHECK(meshes[2].name == "box/lid:blue");
    CHECK(meshes[2].material == 1);
    CHECK(materials.size() == 2);   // no default material needed
    for (const Mesh& m : meshes)
        for (const glm::vec3& p : m.positions) CHECK(p != glm::vec3(9.0f));
}

TEST_CASE("obj: CRLF, blank lines, comments, ignored statements and no final newline", "[obj]") {
    const auto meshes = parse("# c\r\n\r\n  v 0 0 0\r\nv\t1 0 0 1\r\nv 0 1 0 0.5 0.5 0.5\r\ns off\r\nl 1 2\r\n"
                              "vp 0.5\r\ncstype bezier\r\nf 1 2 3   # a trailing comment\r\nf 3 2 +1");
    REQUIRE(meshes.size() == 1);
    CHECK(meshes[0].triangles.size() == 2);
    CHECK(meshes[0].positions[1] == glm::vec3(1, 0, 0));
    // '#' starts a comment only at the start of a word: names may contain it.
    std::vector<Material> materials{Material{.name = "mat#1"}};
    const auto named = parse("o part#2 # the second part\n" + kSquare + "usemtl mat#1\nf 1 2 3\n", materials);
    REQUIRE(named.size() == 1);
    CHECK(named[0].name == "part#2");
    CHECK(named[0].material == 0);
}

TEST_CASE("obj: malformed input names file and line", "[obj]") {
    struct Case {
        std::string text;
        std::string message;
    };
    const std::string eight = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
    const Case cases[] = {
        {eight + "# comment\n\nf 1 2 3\nf 1 2 9\n", "bad.obj:12: face index 9 is past the 8 vertices defined so far"},
        {"v 0 0 0\r\nv 1 0 0\r\n\r\nf 1 2 3\r\n", "bad.obj:4: face index 3 is past the 2 vertices defined so far"},
        {kSquare + "f -5 1 2\n", "bad.obj:5: face index -5 reaches before the first of the 4 vertices defined so far"},
        {kSquare + "f 0 1 2\n", "bad.obj:5: face index 0 is invalid (OBJ indices start at 1; -1 is the last)"},
        {kSquare + "f 1 2\n", "bad.obj:5: face needs at least 3 vertices, got 2"},
        {kSquare + "f\n", "bad.obj:5: face needs at least 3 vertices, got 0"},
        {kSquare + "f a 2 3\n", "bad.obj:5: face index 'a' is not an integer"},
        {kSquare + "f 1.5 2 3\n", "bad.obj:5: face index '1.5' is not an integer"},
        {kSquare + "f 99999999999999999999 2 3\n", "bad.obj:5: face index '99999999999999999999' is not an integer"},
        {kSquare + "f 1/2/3/4 2 3\n", "bad.obj:5: bad face vertex '1/2/3/4' (expected v, v/vt, v//vn or v/vt/vn)"},
        {kSquare + "f /1 2 3\n", "bad.obj:5: bad face vertex '/1' (the vertex index is missing)"},
        {kSquare + "f 1/5 2/1 3/1\n", "bad.obj:5: texture coordinate index 5 is past the 0 texture coordinates defined so far"},
        {kSquare + "vn 0 0 1\nf 1//2 2//1 3//1\n", "bad.obj:6: normal index 2 is past the 1 normals defined so far"},
        {"v 1 2\n", "bad.obj:1: v needs 3 coordinates (optionally followed by w or an RGB colour), got 2"},
        {"v 1 2 3 4 5\n", "bad.obj:1: v needs 3 coordinates (optionally followed by w or an RGB colour), got 5"},
        {"v 1 2 3 4 5 6 7 8\n", "bad.obj:1: v needs 3 coordinates (optionally followed by w or an RGB colour), got more than 6 numbers"},
        {"v 1 2 x\n", "bad.obj:1: v: bad number 'x' (expected a finite decimal number)"},
        {"v 1 2 nan\n", "bad.obj:1: v: bad number 'nan' (expected a finite decimal number)"},
        {"v 1 inf 2\n", "bad.obj:1: v: bad number 'inf' (expected a finite decimal number)"},
        {"v 1e999 0 0\n", "bad.obj:1: v: bad number '1e999' (expected a finite decimal number)"},
        {"v 1e39 0 0\n", "bad.obj:1: v: bad number '1e39' (expected a finite decimal number)"},
        {"v 0x10 0 0\n", "bad.obj:1: v: bad number '0x10' (expected a finite decimal number)"},
        {"v +-1 0 0\n", "bad.obj:1: v: bad number '+-1' (expected a finite decimal number)"},
        {"v 1\xff 0 0\n", "bad.obj:1: v: bad number '1\\xff' (expected a finite decimal number)"},
        {"vn 0 0 0\n", "bad.obj:1: vn has zero length: a normal needs a direction"},
        {"vn 1 0\n", "bad.obj:1: vn needs 3 numbers, got 2"},
        {"vn 1 0 0 1\n", "bad.obj:1: vn needs 3 numbers, got more"},
        {"vt\n", "bad.obj:1: vt needs 1 to 3 numbers, got 0"},
        {"vt 1 2 3 4\n", "bad.obj:1: vt needs 1 to 3 numbers, got more"},
        {"o\n", "bad.obj:1: o needs an object name"},
        {"usemtl  \n", "bad.obj:1: usemtl needs a material name"},
        {"usemtl gold\n", "bad.obj:1: usemtl 'gold': no material of that name (known so far: none; is an mtllib missing?)"},
        {"mtllib\n", "bad.obj:1: mtllib needs a file name"},
        {"mtllib a.mtl\n", "bad.obj:1: mtllib 'a.mtl': no file access when parsing from memory"},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        CHECK(errorOf(c.text) == c.message);
    }
}

TEST_CASE("obj: size limits reject absurd inputs", "[obj]") {
    ObjOptions options;
    options.maxVertices = 3;
    CHECK(errorOf(kSquare, options) == "bad.obj:4: more than 3 vertices (ObjOptions limit)");
    CHECK(errorOf("vn 1 0 0\nvn 1 0 0\nvn 1 0 0\nvn 1 0 0\n", options) ==
          "bad.obj:4: more than 3 normals (ObjOptions limit)");
    options.maxVertices = 100;
    options.maxTriangles = 2;
    CHECK(errorOf(kSquare + "v 2 2 2\nf 1 2 3 4\nf 1 2 5\n", options) == "bad.obj:7: more than 2 triangles (ObjOptions limit)");
    CHECK(errorOf(kSquare + "f 1 2 3 4 1 2 3 4 1 2 3 4\n", options) == "bad.obj:5: more than 2 triangles (ObjOptions limit)");
    CHECK(ObjOptions{}.maxVertices == 50'000'000);
}

TEST_CASE("obj: loadObj reads mtllib beside the file, and missing files are NotFound", "[obj]") {
    const std::string folder = HUSH_TEST_DATA_DIR "/scenes/models/";
    std::vector<Material> materials{Material{.name = "lamp", .emission = {1, 2, 3}}};
    const auto meshes = loadObj(folder + "quad.obj", materials);
    REQUIRE(meshes.size() == 2);
    CHECK(meshes[0].name == "floor");
    CHECK(meshes[0].normals == std::vector<glm::vec3>(4, glm::vec3(0, 1, 0)));
    CHECK(meshes[0].triangles == std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 3}});
    CHECK(meshes[1].name == "lamp");
    CHECK(meshes[1].positions[0] == glm::vec3(-0.2f, 1.9f, -0.2f));
    // The caller's "lamp" wins over the MTL's; "grey" is appended.
    REQUIRE(materials.size() == 2);
    CHECK(materials[meshes[1].material].emission == glm::vec3(1, 2, 3));
    CHECK(materials[meshes[0].material].name == "grey");
    CHECK(materials[1].roughness == Approx(0.1f));

    try {
        loadObj(folder + "missing_mtl.obj", materials);
        FAIL("no error");
    } catch (const hush::Error& e) {
        CHECK(e.kind() == hush::ErrorKind::NotFound);
        CHECK_THAT(e.what(), Catch::StartsWith(folder + "missing_mtl.obj:1: mtllib 'missing.mtl': "));
        CHECK_THAT(e.what(), Catch::Contains("missing.mtl: no such file"));
    }
    try {
        loadObj(folder + "nope.obj", materials);
        FAIL("no error");
    } catch (const hush::Error& e) {
        CHECK(e.kind() == hush::ErrorKind::NotFound);
        CHECK_THAT(e.what(), Catch::Contains("nope.obj"));
    }
}

TEST_CASE("obj: loadMaterials = false uses one material and reads no mtllib", "[obj]") {
    std::vector<Material> materials{Material{.name = "white"}};
    ObjOptions options;
    options.defaultMaterial = "white";
    options.loadMaterials = false;
    const auto meshes = parse("mtllib nowhere.mtl\n" + kSquare + "usemtl gold\nf 1 2 3\n", materials, options);
    REQUIRE(meshes.size() == 1);
    CHECK(meshes[0].material == 0);
    CHECK(materials.size() == 1);
}
