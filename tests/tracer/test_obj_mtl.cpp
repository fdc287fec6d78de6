// MTL parsing: the conversions to hush's material (docs/scene-format.md) and the
// file:line errors.
#include <cmath>

#include <catch2/catch.hpp>

#include <hush/core/error.hpp>
#include <hush/tracer/obj_loader.hpp>

using namespace hush::tracer;

namespace {

std::string errorOf(const std::string& text) {
    try {
        parseMtl(text, "bad.mtl");
    } catch (const hush::Error& e) {
        CHECK(e.kind() == hush::ErrorKind::InvalidArgument);
        return e.what();
    }
    return "(no error)";
}

} // namespace

TEST_CASE("mtl: Kd, Ks, Ke map to albedo, specular and emission", "[mtl]") {
    const auto m = parseMtl("# materials\nnewmtl red paint\n  Kd 0.8 0.1 0.05\nKs 0.04\nKe 1 2 3\nmap_Kd red.png\n"
                            "illum 2\nd 1\nKa 1 1 1\n\nnewmtl plain\r\nPm 1\r\n",
                            "a.mtl");
    REQUIRE(m.size() == 2);
    CHECK(m[0].name == "red paint");
    CHECK(m[0].albedo == glm::vec3(0.8f, 0.1f, 0.05f));
    CHECK(m[0].specular == glm::vec3(0.04f));
    CHECK(m[0].emission == glm::vec3(1, 2, 3));
    CHECK(m[0].roughness == Material{}.roughness);   // neither Ns nor Pr
    // A material with nothing hush reads keeps the defaults.
    CHECK(m[1].name == "plain");
    CHECK(m[1].albedo == Material{}.albedo);
    CHECK(m[1].specular == glm::vec3(0.0f));
    CHECK(m[1].emission == glm::vec3(0.0f));
}

TEST_CASE("mtl: Ns and Pr convert to GGX alpha", "[mtl]") {
    struct Case {
        const char* statements;
        float alpha;
    };
    const Case cases[] = {
        {"Ns 0", 1.0f},                       // sqrt(2 / 2)
        {"Ns 198", 0.1f},                     // sqrt(2 / 200)
        {"Ns 2", std::sqrt(0.5f)},
        {"Ns 1000", std::sqrt(2.0f / 1002.0f)},
        {"Pr 0.5", 0.25f},                    // perceptual roughness squared
        {"Pr 1", 1.0f},
        {"Pr 0", 0.0f},
        {"Ns 10\nPr 0.3", 0.09f},             // Pr wins over Ns, in either order
        {"Pr 0.3\nNs 10", 0.09f},
    };
    for (const Case& c : cases) {
        INFO(c.statements);
        const auto m = parseMtl(std::string("newmtl a\n") + c.statements + "\n", "a.mtl");
        REQUIRE(m.size() == 1);
        CHECK(m[0].roughness == Approx(c.alpha));
    }
    // Ns and Pr belong to the material they follow.
    const auto two = parseMtl("newmtl a\nPr 0.5\nnewmtl b\nNs 0", "a.mtl");
    REQUIRE(two.size() == 2);
    CHECK(two[0].roughness == Approx(0.25f));
    CHECK(two[1].roughness == Approx(1.0f));
}

TEST_CASE("mtl: malformed input names file and line", "[mtl]") {
    struct Case {
        std::string text;
        std::string message;
    };
    const Case cases[] = {
        {"# header\nKd 1 1 1\n", "bad.mtl:2: Kd before any newmtl"},
        {"newmtl\n", "bad.mtl:1: newmtl needs a material name"},
        {"newmtl a\nnewmtl b\nnewmtl a\n", "bad.mtl:3: material 'a' is defined twice (first at line 1)"},
        {"newmtl a\nKd\n", "bad.mtl:2: Kd needs 1 or 3 numbers, got none"},
        {"newmtl a\nKd 1 2\n", "bad.mtl:2: Kd needs 1 or 3 numbers, got 2"},
        {"newmtl a\nKs 1 2 3 4\n", "bad.mtl:2: Ks needs 1 or 3 numbers, got more"},
        {"newmtl a\nKe 1 -2 3\n", "bad.mtl:2: Ke: '-2' is negative (colours must be >= 0)"},
        {"newmtl a\nKd 1 x 3\n", "bad.mtl:2: Kd: bad number 'x' (expected a finite decimal number)"},
        {"newmtl a\nKd nan\n", "bad.mtl:2: Kd: bad number 'nan' (expected a finite decimal number)"},
        {"newmtl a\nKd spectral a.spd\n", "bad.mtl:2: Kd spectral is not supported: give an RGB colour"},
        {"newmtl a\nKd xyz 1 1 1\n", "bad.mtl:2: Kd xyz is not supported: give an RGB colour"},
        {"newmtl a\r\nNs\r\n", "bad.mtl:2: Ns needs a number"},
        {"newmtl a\nNs 1 2\n", "bad.mtl:2: Ns takes one number, got more"},
        {"newmtl a\nNs -1\n", "bad.mtl:2: Ns must be >= 0, got -1.000000"},
        {"newmtl a\nPr 1.5", "bad.mtl:2: Pr must be in [0, 1], got 1.500000"},
        {"newmtl a\nPr 1e400\n", "bad.mtl:2: Pr: bad number '1e400' (expected a finite decimal number)"},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        CHECK(errorOf(c.text) == c.message);
    }
}

TEST_CASE("mtl: loadMtl reads a file, and a missing one is NotFound", "[mtl]") {
    const auto m = loadMtl(HUSH_TEST_DATA_DIR "/scenes/models/quad.mtl");
    REQUIRE(m.size() == 2);
    CHECK(m[0].name == "grey");
    CHECK(m[0].specular == glm::vec3(0.04f));
    CHECK(m[1].emission == glm::vec3(10.0f));
    try {
        loadMtl(HUSH_TEST_DATA_DIR "/scenes/models/none.mtl");
        FAIL("no error");
    } catch (const hush::Error& e) {
        CHECK(e.kind() == hush::ErrorKind::NotFound);
        CHECK_THAT(e.what(), Catch::Contains("none.mtl"));
    }
}
