// Replays the kept fuzz corpus (tests/tracer/data/fuzz_corpus, grown by
// scripts/fuzz.sh) in the normal g++ build: every input must either parse into
// consistent data or throw hush::Error, never anything else. Inputs that once
// crashed a parser are kept there, so this is the regression test for each fix.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <catch2/catch.hpp>

#include <hush/core/error.hpp>
#include <hush/tracer/scene_file.hpp>

#include "../fuzz/fuzz_files.hpp"   // the in-memory files the fuzz harnesses use
#include "../fuzz/fuzz_replay.hpp"  // the corpus files

using namespace hush::tracer;

namespace {

std::vector<std::filesystem::path> corpus(const char* parser) {
    return hush::fuzz::corpusFiles(std::string(HUSH_TEST_DATA_DIR "/fuzz_corpus/") + parser);
}

std::string contents(const std::filesystem::path& path) {
    const auto bytes = hush::fuzz::fileBytes(path);
    return {bytes.begin(), bytes.end()};
}

// Runs `parse` on every corpus file; returns how many parsed without an error.
template <class Parse>
std::size_t replay(const char* parser, Parse parse) {
    const auto files = corpus(parser);
    REQUIRE(files.size() >= 3);   // the seeds at least
    std::size_t parsed = 0;
    for (const auto& file : files) {
        INFO(file.string());
        const std::string text = contents(file);
        try {
            parse(text);
            ++parsed;
        } catch (const hush::Error& e) {
            CHECK(std::string(e.what()).size() > 0);
        } catch (const std::exception& e) {
            FAIL("threw something other than hush::Error: " << e.what());
        } catch (...) {
            FAIL("threw something other than hush::Error");
        }
    }
    return parsed;
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

} // namespace

TEST_CASE("scene files: every fuzz corpus input parses or throws hush::Error (obj)", "[obj][scene][fuzz]") {
    const std::size_t parsed = replay("obj", [](const std::string& text) {
        std::vector<Material> materials{Material{.name = "preset"}};
        ObjOptions options;
        options.maxVertices = 100'000;   // as in tests/fuzz/fuzz_obj.cpp
        options.maxTriangles = 100'000;
        for (const Mesh& m : parseObj(text, "fuzz.obj", materials, options, hush::fuzz::memoryReader(text))) {
            REQUIRE(m.material < materials.size());
            REQUIRE((m.normals.empty() || m.normals.size() == m.positions.size()));
            for (const auto& t : m.triangles) REQUIRE(glm::all(glm::lessThan(t, glm::uvec3(m.positions.size()))));
            for (const auto& p : m.positions) REQUIRE(finite(p));
        }
    });
    CHECK(parsed > 0);
}

TEST_CASE("scene files: every fuzz corpus input parses or throws hush::Error (mtl)", "[mtl][scene][fuzz]") {
    const std::size_t parsed = replay("mtl", [](const std::string& text) {
        for (const Material& m : parseMtl(text, "fuzz.mtl")) {
            REQUIRE(!m.name.empty());
            REQUIRE((std::isfinite(m.roughness) && m.roughness >= 0.0f));
            REQUIRE((finite(m.albedo) && finite(m.specular) && finite(m.emission)));
        }
    });
    CHECK(parsed > 0);
}

TEST_CASE("scene files: every fuzz corpus input parses or throws hush::Error (scene)", "[scene][fuzz]") {
    const std::size_t parsed = replay("scene", [](const std::string& text) {
        const Scene s = parseSceneFile(text, "fuzz.json", hush::fuzz::memoryReader(text));
        s.validate();
    });
    CHECK(parsed > 0);
}
