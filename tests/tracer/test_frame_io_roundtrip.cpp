// Frame I/O round trips: float channels bit-exact (special values included), half
// channels within fp16 precision, meshid exact, camera and metadata exact; channel
// subsets; the stored pixel types; sequence naming and listing.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include <Imath/half.h>

#include <hush/core/error.hpp>
#include <hush/tracer/frame_io.hpp>

#include "test_frame_io_support.hpp"

using namespace hush::tracer;
using hush::tracer::test::TempDir;
namespace fs = std::filesystem;

namespace {

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

bool sameCamera(const CameraInfo& a, const CameraInfo& b) {
    return a.view == b.view && a.projection == b.projection && a.jitter == b.jitter && a.position == b.position &&
           a.verticalFovDegrees == b.verticalFovDegrees && a.nearPlane == b.nearPlane && a.farPlane == b.farPlane;
}

// Values that must survive float storage bit for bit.
const uint32_t kFloatSpecials[] = {
    0x7F800000u,   // +Inf
    0xFF800000u,   // -Inf
    0x80000000u,   // -0.0
    0x00000001u,   // smallest denormal
    0x000A1B2Cu,   // another denormal
    0x80400000u,   // negative denormal
    0x7FC12345u,   // quiet NaN with a payload
    0x7F800001u,   // signalling NaN
    0xFFC00001u,   // negative NaN
    0x7F7FFFFFu,   // FLT_MAX
};

void putFloatSpecials(Image& image) {
    for (size_t i = 0; i < std::size(kFloatSpecials) && i < image.pixels.size(); ++i)
        image.pixels[i] = std::bit_cast<float>(kFloatSpecials[i]);
}

ExrCompression compressionNamed(int i) {
    return i == 0 ? ExrCompression::None : i == 1 ? ExrCompression::Zip : ExrCompression::Piz;
}

} // namespace

TEST_CASE("frame round trip: float channels are bit-exact, half within fp16, meshid and camera exact",
          "[frame_io]") {
    TempDir dir;
    for (auto [width, height] : {std::pair{13u, 7u}, std::pair{64u, 48u}}) {
        for (int c = 0; c < 3; ++c) {
            INFO("size " << width << "x" << height << ", compression " << c);
            Frame frame = test::makeFullFrame(width, height);
            frame.metresPerUnit = 0.001f;
            for (Channel channel : kAllChannels)
                if (channelInfo(channel).storedAs == PixelKind::Float) putFloatSpecials(frame.channels[channel]);
            const std::string path = dir.file("frame.exr");
            writeFrame(frame, path, {.compression = compressionNamed(c)});
            const Frame back = readFrame(path);

            CHECK(back.width == width);
            CHECK(back.height == height);
            CHECK(back.index == 42);
            CHECK(back.scene == frame.scene);
            CHECK(back.referenceSpp == 1024);
            CHECK(back.metresPerUnit == 0.001f);
            CHECK(sameCamera(back.camera, frame.camera));
            CHECK(sameCamera(back.previousCamera, frame.previousCamera));
            REQUIRE(back.channels.size() == std::size(kAllChannels));
            for (Channel channel : kAllChannels) {
                INFO("channel " << channelInfo(channel).name);
                const Image& in = frame.get(channel);
                const Image& out = back.get(channel);
                REQUIRE(out.width == width);
                REQUIRE(out.height == height);
                REQUIRE(out.channels == channelInfo(channel).components);
                if (channelInfo(channel).storedAs != PixelKind::Half) {
                    CHECK(sameBits(in.pixels, out.pixels));   // float and meshid
                    continue;
                }
                for (size_t i = 0; i < in.pixels.size(); ++i) {
                    const float v = in.pixels[i];
                    // Round to nearest half: relative error 2^-11, or 2^-25 below the normals.
                    const float tolerance = std::max(std::fabs(v) * 0x1p-11f, 0x1p-25f);
                    if (std::fabs(out.pixels[i] - v) > tolerance)
                        FAIL("value " << i << ": " << v << " -> " << out.pixels[i]);
                }
            }
            CHECK(dir.entries() == std::vector<std::string>{"frame.exr"});   // no temporary left behind
        }
    }
}

TEST_CASE("frame round trip: values representable in fp16 are bit-exact in half channels", "[frame_io]") {
    TempDir dir;
    Frame frame;
    frame.width = 13;
    frame.height = 7;
    Image& color = frame.add(Channel::Color);
    for (size_t i = 0; i < color.pixels.size(); ++i)   // multiples of 1/1024 below 2048 fit fp16's 11 bits
        color.pixels[i] = float(int(i * 37 % 4001) - 2000) / 1024.0f;
    const float specials[] = {std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(), -0.0f,
                              65504.0f, -65504.0f, 0x1p-24f /* smallest fp16 denormal */, 0x1p-14f, 1.0f};
    std::copy(std::begin(specials), std::end(specials), color.pixels.begin());
    const std::string path = dir.file("frame.exr");
    writeFrame(frame, path);
    const Frame back = readFrame(path);
    CHECK(sameBits(back.get(Channel::Color).pixels, color.pixels));
}

TEST_CASE("frame writing: half channels clamp fireflies and keep NaN", "[frame_io]") {
    TempDir dir;
    Frame frame;
    frame.width = 4;
    frame.height = 1;
    Image& color = frame.add(Channel::Color);
    color.pixels = {1e6f, -1e6f, std::nanf(""), 65519.0f, 70000.0f, 1e-9f, 0.5f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f};
    writeFrame(frame, dir.file("f.exr"));
    const Frame back = readFrame(dir.file("f.exr"));
    const auto& out = back.get(Channel::Color).pixels;
    CHECK(out[0] == 65504.0f);   // a finite firefly stays finite
    CHECK(out[1] == -65504.0f);
    CHECK(std::isnan(out[2]));
    CHECK(out[3] == 65504.0f);
    CHECK(out[4] == 65504.0f);
    CHECK(out[5] == 0.0f);   // below half's smallest denormal
}

TEST_CASE("frame writing: allFloat makes half channels bit-exact and types follow storedAs", "[frame_io]") {
    TempDir dir;
    Frame frame = test::makeFullFrame(13, 7);
    putFloatSpecials(frame.channels[Channel::Color]);
    const std::string path = dir.file("frame.exr");

    writeFrame(frame, path);
    FrameFileInfo info = readFrameInfo(path);
    CHECK(info.width == 13);
    CHECK(info.height == 7);
    CHECK(info.compression == "zip");
    CHECK(info.layers.size() == std::size(kAllChannels));
    size_t expectedChannels = 0;
    for (Channel channel : kAllChannels) expectedChannels += channelInfo(channel).components;
    REQUIRE(info.exrChannels.size() == expectedChannels);
    for (const auto& channel : info.exrChannels) {
        INFO(channel.name);
        const auto layer = parseChannel(channel.name.substr(0, channel.name.find('.')));
        REQUIRE(layer);
        CHECK(channel.type == channelInfo(*layer).storedAs);
    }

    writeFrame(frame, path, {.compression = ExrCompression::Piz, .allFloat = true});
    info = readFrameInfo(path);
    CHECK(info.compression == "piz");
    for (const auto& channel : info.exrChannels)
        CHECK(channel.type == (channel.name == "meshid.ID" ? PixelKind::Uint : PixelKind::Float));
    const Frame back = readFrame(path);
    for (Channel channel : kAllChannels) {
        INFO(channelInfo(channel).name);
        CHECK(sameBits(back.get(channel).pixels, frame.get(channel).pixels));
    }
}

TEST_CASE("frame reading: meshid ids and kNoMesh are exact and the float mapping is total", "[frame_io]") {
    TempDir dir;
    Frame frame;
    frame.width = 3;
    frame.height = 2;
    frame.add(Channel::MeshId).pixels = {0.0f, 1.0f, 12345.0f, 16777215.0f, kNoMesh, 7.0f};
    writeFrame(frame, dir.file("ids.exr"));
    CHECK(readFrame(dir.file("ids.exr")).get(Channel::MeshId).pixels == frame.get(Channel::MeshId).pixels);

    CHECK(meshIdFromPixel(kNoMesh) == kNoMeshOnDisk);
    CHECK(meshIdFromPixel(std::nanf("")) == kNoMeshOnDisk);
    CHECK(meshIdFromPixel(-5.0f) == kNoMeshOnDisk);
    CHECK(meshIdFromPixel(4294967296.0f) == kNoMeshOnDisk);
    CHECK(meshIdFromPixel(16777215.0f) == 16777215u);
    CHECK(meshIdToPixel(kNoMeshOnDisk) == kNoMesh);
    CHECK(meshIdToPixel(3u) == 3.0f);
}

TEST_CASE("frame reading: a subset of channels, and requested channels that are absent", "[frame_io]") {
    TempDir dir;
    const Frame frame = test::makeFullFrame(13, 7);
    const std::string path = dir.file("frame.exr");
    writeFrame(frame, path);

    const Frame subset = readFrame(path, {.channels = {Channel::Depth, Channel::Motion, Channel::Depth}});
    CHECK(subset.channels.size() == 2);
    CHECK(sameBits(subset.get(Channel::Depth).pixels, frame.get(Channel::Depth).pixels));
    CHECK(sameBits(subset.get(Channel::Motion).pixels, frame.get(Channel::Motion).pixels));
    CHECK(sameCamera(subset.camera, frame.camera));

    Frame colorOnly;
    colorOnly.width = 13;
    colorOnly.height = 7;
    colorOnly.add(Channel::Color);
    writeFrame(colorOnly, path);
    try {
        readFrame(path, {.channels = {Channel::Color, Channel::Albedo}});
        FAIL("expected an error");
    } catch (const hush::Error& e) {
        CHECK(e.kind() == hush::ErrorKind::NotFound);
        CHECK_THAT(e.what(), Catch::Contains(path) && Catch::Contains("albedo") && Catch::Contains("color"));
    }
    const Frame lenient = readFrame(path, {.channels = {Channel::Color, Channel::Albedo}, .requireChannels = false});
    CHECK(lenient.has(Channel::Color));
    CHECK_FALSE(lenient.has(Channel::Albedo));

    CHECK(readFrame(path, {.expectedWidth = 13, .expectedHeight = 7}).width == 13);
    CHECK_THROWS_WITH(readFrame(path, {.expectedWidth = 14}),
                      Catch::Contains(path) && Catch::Contains("13x7") && Catch::Contains("expected 14x"));
}

TEST_CASE("frame sequences: framePath pads to 4 digits, listFrames sorts by index", "[frame_io]") {
    CHECK(framePath("out", 0) == "out/frame_0000.exr");
    CHECK(framePath("out/", 12) == "out/frame_0012.exr");
    CHECK(framePath("/a/b", 12345) == "/a/b/frame_12345.exr");

    TempDir dir;
    const std::string folder = dir.path().string();
    CHECK_THROWS_WITH(listFrames(folder), Catch::Contains(folder) && Catch::Contains("frame_"));
    CHECK_THROWS_WITH(listFrames(dir.file("missing")), Catch::Contains(dir.file("missing")));

    for (const char* name : {"frame_0010.exr", "frame_0002.exr", "frame_10000.exr", "frame_0000.exr",
                             "frame_0003.exr.tmp-99", "frame_x.exr", "notes.txt", "frame_.exr"})
        std::ofstream(dir.file(name)) << "x";
    fs::create_directory(dir.file("frame_0005.exr"));   // a folder is not a frame
    const std::vector<std::string> expected = {framePath(folder, 0), framePath(folder, 2), framePath(folder, 10),
                                               framePath(folder, 10000)};
    CHECK(listFrames(folder) == expected);

    std::ofstream(dir.file("frame_2.exr")) << "x";   // a second file for frame 2
    CHECK_THROWS_WITH(listFrames(folder), Catch::Contains("frame_2.exr") && Catch::Contains("frame_0002.exr"));
}

TEST_CASE("frame round trip through a sequence keeps each frame's index", "[frame_io]") {
    TempDir dir;
    const std::string folder = dir.path().string();
    for (uint32_t i = 0; i < 3; ++i) {
        Frame frame = test::makeFullFrame(13, 7);
        frame.index = i;
        writeFrame(frame, framePath(folder, i), {.compression = ExrCompression::None});
    }
    const auto paths = listFrames(folder);
    REQUIRE(paths.size() == 3);
    for (uint32_t i = 0; i < 3; ++i) CHECK(readFrame(paths[i], {.channels = {Channel::Depth}}).index == i);
}

TEST_CASE("frame round trip with OpenEXR worker threads is still bit-exact", "[frame_io]") {
    TempDir dir;
    Frame frame = test::makeFullFrame(64, 48);
    setFrameIoThreadCount(3);
    writeFrame(frame, dir.file("frame.exr"), {.allFloat = true});
    const Frame back = readFrame(dir.file("frame.exr"));
    setFrameIoThreadCount(0);   // leave the process as the other tests expect it
    for (Channel channel : kAllChannels) CHECK(sameBits(back.get(channel).pixels, frame.get(channel).pixels));
}
