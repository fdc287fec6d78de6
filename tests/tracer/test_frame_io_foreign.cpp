// Files from elsewhere: a frame written by "another renderer" (the test's own raw
// OpenEXR writer, following docs/frame-format.md), and the BMFR authors' dataset
// layout with a text camera file.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <hush/core/error.hpp>
#include <hush/tracer/bmfr_dataset.hpp>
#include <hush/tracer/frame_io.hpp>

#include "test_frame_io_support.hpp"

using namespace hush::tracer;
using hush::tracer::test::RawExr;
using hush::tracer::test::TempDir;
namespace fs = std::filesystem;

TEST_CASE("frame reading: another renderer's file with only color.R/G/B loads", "[frame_io]") {
    TempDir dir;
    const std::string path = dir.file("frame_0007.exr");
    RawExr exr(13, 7);
    exr.addFloat("color.R", [](int x, int) { return float(x) + 0.25f; });
    exr.addFloat("color.G", [](int, int y) { return float(y) * 1e-3f; });
    exr.addFloat("color.B", [](int x, int y) { return x == 3 && y == 2 ? -0.0f : 1e30f; });
    exr.addFloat("A", [](int, int) { return 1.0f; });              // not a hush layer: ignored
    exr.addFloat("diffuse.R", [](int, int) { return 2.0f; });      // ditto
    exr.addFloat("beauty.color.R", [](int, int) { return 3.0f; }); // nested: ditto
    exr.addStringAttribute("owner", "someone else");
    test::writeRawExr(path, exr);

    const Frame frame = readFrame(path);
    CHECK(frame.width == 13);
    CHECK(frame.height == 7);
    CHECK(frame.index == 7);   // from the file name, as there is no hush.frameIndex
    CHECK(frame.scene.empty());
    CHECK(frame.referenceSpp == 0);
    const CameraInfo defaults;
    CHECK(frame.camera.view == defaults.view);
    CHECK(frame.camera.projection == defaults.projection);
    CHECK(frame.camera.verticalFovDegrees == defaults.verticalFovDegrees);
    CHECK(frame.previousCamera.view == defaults.view);
    REQUIRE(frame.channels.size() == 1);
    const Image& color = frame.get(Channel::Color);
    CHECK(color.at(5, 0)[0] == 5.25f);   // rows and columns land where they were written
    CHECK(color.at(0, 6)[1] == 6e-3f);
    CHECK(std::bit_cast<uint32_t>(color.at(3, 2)[2]) == 0x80000000u);
    CHECK(color.at(12, 6)[2] == 1e30f);
    CHECK_THROWS_WITH(readFrame(path, {.channels = {Channel::Normal}}), Catch::Contains("no layer 'normal'"));
}

TEST_CASE("frame reading: a file with none of hush's layers says so and lists its channels", "[frame_io]") {
    // Another renderer's beauty and depth passes (not Cycles': no "<layer>.Combined.R").
    TempDir dir;
    const std::string path = dir.file("frame_0001.exr");
    RawExr exr(4, 3);
    for (const char* name : {"beauty.R", "beauty.G", "beauty.B", "Z"}) exr.addFloat(name, [](int, int) { return 1.0f; });
    test::writeRawExr(path, exr);
    CHECK_THROWS_WITH(readFrame(path), Catch::Contains(path) && Catch::Contains("none of hush's layers") &&
                                           Catch::Contains("beauty.R") && Catch::Contains("frame-format.md"));
}

TEST_CASE("frame reading: foreign camera attributes, ids and pixel types follow the contract", "[frame_io]") {
    TempDir dir;
    const std::string path = dir.file("shot.exr");
    RawExr exr(3, 2);
    // meshid as UINT with kNoMeshOnDisk, and a float meshid from a renderer that uses -1.
    exr.addUint("meshid.ID", {0u, 1u, 16777215u, 0xFFFFFFFFu, 9u, 2u});
    exr.addFloat("depth.Z", [](int x, int) { return 1.5f * float(x + 1); });
    // The matrix as 16 floats in file order: a translation by (4, 5, 6) sits in
    // elements 12..14, as Imath's M44f (row vectors) and glm's mat4 [3][0..2] both have it.
    std::vector<float> translate = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 4, 5, 6, 1};
    exr.addFloatAttribute("hush.camera.view", translate, "m44f");
    exr.addFloatAttribute("hush.camera.jitter", {0.25f, -0.5f}, "v2f");
    exr.addFloatAttribute("hush.camera.fov", {60.0f}, "float");
    exr.addIntAttribute("hush.frameIndex", 3);
    test::writeRawExr(path, exr);

    const Frame frame = readFrame(path);
    CHECK(frame.index == 3);
    CHECK(frame.camera.view[3] == glm::vec4(4, 5, 6, 1));
    CHECK(frame.camera.view * glm::vec4(0, 0, 0, 1) == glm::vec4(4, 5, 6, 1));
    CHECK(frame.camera.jitter == glm::vec2(0.25f, -0.5f));
    CHECK(frame.camera.verticalFovDegrees == 60.0f);
    CHECK(frame.camera.nearPlane == CameraInfo{}.nearPlane);   // absent: default
    // No hush.previousCamera.*: the previous camera is the current one.
    CHECK(frame.previousCamera.view == frame.camera.view);
    CHECK(frame.previousCamera.jitter == frame.camera.jitter);
    CHECK(frame.get(Channel::MeshId).pixels == std::vector<float>{0, 1, 16777215, kNoMesh, 9, 2});
    CHECK(frame.get(Channel::Depth).at(2, 1)[0] == 4.5f);

    RawExr floatIds(3, 1);
    floatIds.addFloat("meshid.ID", [](int x, int) { return x == 0 ? -1.0f : x == 1 ? 5.0f : std::nanf(""); });
    test::writeRawExr(path, floatIds);
    CHECK(readFrame(path).get(Channel::MeshId).pixels == std::vector<float>{kNoMesh, 5.0f, kNoMesh});
}

namespace {

// The BMFR layout: <buffer><N>.exr, RGB float, written raw as their renderer would.
void writeBmfrImage(const std::string& path, int width, int height, float base) {
    RawExr exr(width, height);
    exr.addFloat("R", [&](int x, int) { return base + float(x); });
    exr.addFloat("G", [&](int, int y) { return base + float(y); });
    exr.addFloat("B", [&](int x, int y) { return base - float(x * y); });
    exr.addFloat("A", [](int, int) { return 1.0f; });   // an alpha some writers add: ignored
    test::writeRawExr(path, exr);
}

void writeBmfrFolder(const TempDir& dir, uint32_t frames) {
    const char* buffers[] = {"color", "shading_normal", "world_position", "albedo"};
    for (uint32_t n = 0; n < frames; ++n)
        for (size_t b = 0; b < 4; ++b)
            writeBmfrImage(dir.file(buffers[b] + std::to_string(n) + ".exr"), 13, 7, float(100 * n + 10 * b));
}

} // namespace

TEST_CASE("BMFR dataset frames: the images and the text camera file map onto hush channels", "[frame_io][bmfr]") {
    TempDir dir;
    writeBmfrFolder(dir, 2);
    writeBmfrImage(dir.file("reference1.exr"), 13, 7, 7.0f);
    CHECK(countBmfrFrames(dir.path().string()) == 2);
    CHECK(countBmfrFrames(dir.file("missing")) == 0);

    const std::string cameraPath = dir.file("cameras.txt");
    {
        std::ofstream cameras(cameraPath);
        cameras << "# view-projection, row-major; optional jitter\n\n";
        cameras << "1 0 0 0, 0 1 0 0, 0 0 1 0, 0 0 0 1\n";
        cameras << "2 0 0 0.5\t0 2 0 -1 0 0 1 0 0 0 -1 0 0.25 -0.25\r\n";
    }
    const BmfrCameraData camera = readBmfrCameraFile(cameraPath);
    REQUIRE(camera.viewProjection.size() == 2);
    CHECK(camera.viewProjection[0] == glm::mat4(1.0f));
    // Row-major in the file: row 0 is (2 0 0 0.5), so x' = 2x + 0.5w.
    CHECK(camera.viewProjection[1] * glm::vec4(1, 1, 1, 1) == glm::vec4(2.5f, 1.0f, 1.0f, -1.0f));
    CHECK(camera.jitter[0] == glm::vec2(0.0f));
    CHECK(camera.jitter[1] == glm::vec2(0.25f, -0.25f));

    const Frame frame = readBmfrFrame(dir.path().string(), 1, &camera);
    CHECK(frame.width == 13);
    CHECK(frame.height == 7);
    CHECK(frame.index == 1);
    CHECK(frame.channels.size() == 5);
    // color1.exr holds demodulated illumination (104 at R of (4, 2)); albedo1.exr 134
    // there: hush's colour is their product, full radiance.
    CHECK(frame.get(Channel::Color).at(4, 2)[0] == 104.0f * 134.0f);
    CHECK(frame.get(Channel::Normal).at(4, 2)[1] == 112.0f);
    CHECK(frame.get(Channel::Position).at(4, 2)[2] == 120.0f - 8.0f);
    CHECK(frame.get(Channel::Albedo).at(0, 6)[1] == 136.0f);
    CHECK(frame.get(Channel::Reference).at(1, 1)[0] == 8.0f);
    CHECK(frame.camera.projection * frame.camera.view == camera.viewProjection[1]);
    CHECK(frame.camera.jitter == camera.jitter[1]);
    CHECK(frame.previousCamera.projection == camera.viewProjection[0]);

    const Frame first = readBmfrFrame(dir.path().string(), 0);   // no camera: defaults, no reference
    CHECK(first.channels.size() == 4);
    CHECK(first.camera.projection == CameraInfo{}.projection);

    // Round trip into hush's own format.
    writeFrame(frame, framePath(dir.file(""), 1), {.allFloat = true});
    CHECK(readFrame(framePath(dir.file(""), 1)).get(Channel::Normal).pixels == frame.get(Channel::Normal).pixels);
}

TEST_CASE("BMFR dataset frames: missing or mismatched files and bad camera lines are named", "[frame_io][bmfr]") {
    TempDir dir;
    writeBmfrFolder(dir, 1);
    const std::string folder = dir.path().string();
    CHECK_THROWS_WITH(readBmfrFrame(folder, 1), Catch::Contains("color1.exr") && Catch::Contains("no such file"));

    fs::remove(dir.file("albedo0.exr"));
    CHECK_THROWS_WITH(readBmfrFrame(folder, 0), Catch::Contains(dir.file("albedo0.exr")));
    writeBmfrImage(dir.file("albedo0.exr"), 12, 7, 0.0f);
    CHECK_THROWS_WITH(readBmfrFrame(folder, 0), Catch::Contains(dir.file("albedo0.exr")) && Catch::Contains("12x7") &&
                                                    Catch::Contains("13x7"));
    RawExr grey(13, 7);
    grey.addFloat("Y", [](int, int) { return 0.5f; });
    test::writeRawExr(dir.file("albedo0.exr"), grey);
    CHECK_THROWS_WITH(readBmfrFrame(folder, 0), Catch::Contains(dir.file("albedo0.exr")) && Catch::Contains("'R'"));
    writeBmfrImage(dir.file("albedo0.exr"), 13, 7, 0.0f);

    const std::string cameraPath = dir.file("cameras.txt");
    std::ofstream(cameraPath) << "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n# ok\n1 2 3\n";
    CHECK_THROWS_WITH(readBmfrCameraFile(cameraPath), Catch::Contains(cameraPath) && Catch::Contains("line 3") &&
                                                          Catch::Contains("found 3"));
    std::ofstream(cameraPath) << "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 x1\n";
    CHECK_THROWS_WITH(readBmfrCameraFile(cameraPath), Catch::Contains("line 1") && Catch::Contains("'x1'"));
    std::ofstream(cameraPath) << "# nothing\n";
    CHECK_THROWS_WITH(readBmfrCameraFile(cameraPath), Catch::Contains("no cameras"));
    CHECK_THROWS_WITH(readBmfrCameraFile(dir.file("none.txt")), Catch::Contains(dir.file("none.txt")));

    BmfrCameraData oneCamera;
    oneCamera.viewProjection.resize(1, glm::mat4(1.0f));
    oneCamera.jitter.resize(1);
    CHECK_NOTHROW(readBmfrFrame(folder, 0, &oneCamera));
    writeBmfrFolder(dir, 2);
    CHECK_THROWS_WITH(readBmfrFrame(folder, 1, &oneCamera), Catch::Contains("1 frames"));
}
