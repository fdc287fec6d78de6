// Blender Cycles multilayer files read as hush frames (docs/blender.md), on a fixture
// Blender 3.4.1 rendered (tests/tracer/data/cycles/README.md): the passes map onto
// hush's layers, and the conventions hold as hush check measures them.
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <hush/tracer/frame_check.hpp>
#include <hush/tracer/frame_io.hpp>

#include "test_frame_io_support.hpp"

using namespace hush::tracer;
using hush::tracer::test::RawExr;

namespace {

const std::string kFrames = std::string(HUSH_TEST_DATA_DIR) + "/cycles/frames";
const std::string kReference = std::string(HUSH_TEST_DATA_DIR) + "/cycles/reference";

std::vector<Frame> fixtureFrames() {
    std::vector<Frame> frames;
    for (const std::string& path : listFrames(kFrames)) frames.push_back(readFrame(path));
    return frames;
}

} // namespace

TEST_CASE("cycles: a multilayer file's passes become hush layers", "[frame_io][cycles]") {
    const auto files = listFrames(kFrames);
    REQUIRE(files.size() == 4);
    const FrameFileInfo info = readFrameInfo(files[0]);
    const std::set<Channel> layers(info.layers.begin(), info.layers.end());
    for (Channel c : {Channel::Color, Channel::Direct, Channel::Indirect, Channel::Emission, Channel::Albedo,
                      Channel::Normal, Channel::Position, Channel::Depth, Channel::Motion, Channel::MeshId})
        CHECK(layers.count(c) == 1);
    const Frame frame = readFrame(files[1]);
    CHECK(frame.width == 32);
    CHECK(frame.index == 2);   // from the file name, as Blender numbers frames from 1
    const auto& color = frame.get(Channel::Color).pixels;
    const auto& direct = frame.get(Channel::Direct).pixels;
    const auto& indirect = frame.get(Channel::Indirect).pixels;
    double worst = 0.0;
    for (size_t i = 0; i < color.size(); ++i)
        worst = std::max(worst, std::fabs(double(color[i]) - direct[i] - indirect[i]) / std::max(1e-3, double(color[i])));
    CHECK(worst < 1e-4);   // Combined = sum of (Dir + Ind) * Col + Emit + Env
    std::set<float> ids;
    size_t misses = 0;
    const auto& meshId = frame.get(Channel::MeshId).pixels;
    const auto& depth = frame.get(Channel::Depth).pixels;
    float nearestMiss = 1e30f, farthestHit = 0.0f;
    for (size_t i = 0; i < meshId.size(); ++i) {
        if (meshId[i] == kNoMesh) ++misses, nearestMiss = std::min(nearestMiss, depth[i]);
        else ids.insert(meshId[i]), farthestHit = std::max(farthestHit, depth[i]);
    }
    CHECK(ids == std::set<float>{1.0f, 2.0f, 3.0f});   // the objects' pass indices
    CHECK(misses > 0);
    CHECK(nearestMiss > farthestHit);                    // misses at a far plane, not 1e10
    CHECK(nearestMiss < 1e9f);
}

TEST_CASE("cycles: the fixture follows hush's conventions as hush check measures them", "[frame_io][cycles]") {
    const std::vector<Frame> frames = fixtureFrames();
    for (const ConventionCheck& check : checkFrameConventions(frames)) {
        INFO(check.convention << ": " << check.evidence);
        if (check.convention == "camera" || check.convention == "depth")
            CHECK(check.verdict == CheckVerdict::Skipped);   // Cycles writes no camera matrices
        else
            CHECK(check.verdict == CheckVerdict::Pass);       // motion's sign and y, world normals, ...
    }
}

TEST_CASE("cycles: a layer the passes cannot make is named with the Blender setting", "[frame_io][cycles]") {
    const std::string first = listFrames(kFrames)[0];
    CHECK_THROWS_WITH(readFrame(first, {.channels = {Channel::Specular}}),
                      Catch::Contains("Blender Cycles") && Catch::Contains("'specular'"));
    test::TempDir dir;
    const std::string path = dir.file("frame_0001.exr");
    RawExr exr(4, 3);
    for (const char* name : {"Scene.Combined.R", "Scene.Combined.G", "Scene.Combined.B", "Scene.Combined.A"})
        exr.addFloat(name, [](int x, int) { return float(x); });
    hush::tracer::test::writeRawExr(path, exr);
    const Frame colourOnly = readFrame(path);   // a renamed view layer is found too
    CHECK(colourOnly.has(Channel::Color));
    CHECK(colourOnly.get(Channel::Color).at(3, 0)[0] == 3.0f);
    CHECK_THROWS_WITH(readFrame(path, {.channels = {Channel::Motion}}),
                      Catch::Contains(path) && Catch::Contains("Vector") && Catch::Contains("motion blur off"));
}
