// Frame I/O failures: writes that fail leave neither a temporary nor a damaged
// destination; reads of missing, foreign-format, truncated or malformed files throw
// hush::Error naming the file and the problem.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <hush/core/error.hpp>
#include <hush/tracer/frame_io.hpp>

#include "test_frame_io_support.hpp"

using namespace hush::tracer;
using hush::tracer::test::RawExr;
using hush::tracer::test::TempDir;
namespace fs = std::filesystem;

namespace {

Frame smallFrame() {
    Frame frame;
    frame.width = 13;
    frame.height = 7;
    frame.add(Channel::Color);
    frame.add(Channel::Depth).pixels.assign(13 * 7, 2.5f);
    return frame;
}

// A foreign file with a complete color layer plus whatever `extra` adds.
template <class F> void writeColorFile(const std::string& path, F extra) {
    RawExr exr(13, 7);
    for (const char* c : {"color.R", "color.G", "color.B"}) exr.addFloat(c, [](int x, int y) { return x + 0.5f * y; });
    extra(exr);
    test::writeRawExr(path, exr);
}

} // namespace

TEST_CASE("frame writing: a missing folder throws naming the path and creates nothing", "[frame_io]") {
    TempDir dir;
    const std::string path = dir.file("missing/frame_0000.exr");
    try {
        writeFrame(smallFrame(), path);
        FAIL("expected an error");
    } catch (const hush::Error& e) {
        CHECK(e.kind() == hush::ErrorKind::NotFound);
        CHECK_THAT(e.what(), Catch::Contains(path) && Catch::Contains("does not exist"));
    }
    CHECK(dir.entries().empty());
}

TEST_CASE("frame writing: a failure after the temporary is written removes it", "[frame_io]") {
    // The rename onto a non-empty folder fails only after the whole file is written:
    // the late failure path must still clean up (running as root, chmod cannot do this).
    TempDir dir;
    const std::string path = dir.file("frame_0000.exr");
    fs::create_directory(path);
    std::ofstream(dir.file("frame_0000.exr/keep.txt")) << "keep";
    CHECK_THROWS_WITH(writeFrame(smallFrame(), path), Catch::Contains(path));
    CHECK(dir.entries() == std::vector<std::string>{"frame_0000.exr"});
    CHECK(fs::is_directory(path));
    CHECK(fs::exists(dir.file("frame_0000.exr/keep.txt")));
}

TEST_CASE("frame writing: an inconsistent frame throws before touching an existing file", "[frame_io]") {
    TempDir dir;
    const std::string path = dir.file("frame_0003.exr");
    writeFrame(smallFrame(), path);
    const auto before = test::fileBytes(path);

    Frame wrongSize = smallFrame();
    wrongSize.channels[Channel::Depth].pixels.resize(13 * 6);
    Frame wrongComponents = smallFrame();
    wrongComponents.channels[Channel::Color] = Image(13, 7, 4);
    Frame wrongWidth = smallFrame();
    wrongWidth.channels[Channel::Color] = Image(12, 7, 3);
    Frame empty;
    Frame noChannels = smallFrame();
    noChannels.channels.clear();
    const std::pair<const Frame*, const char*> cases[] = {{&wrongSize, "depth"},
                                                          {&wrongComponents, "color"},
                                                          {&wrongWidth, "color"},
                                                          {&empty, "empty"},
                                                          {&noChannels, "no channels"}};
    for (const auto& [frame, word] : cases) {
        try {
            writeFrame(*frame, path);
            FAIL("expected an error mentioning " << word);
        } catch (const hush::Error& e) {
            CHECK(e.kind() == hush::ErrorKind::InvalidArgument);
            CHECK_THAT(e.what(), Catch::Contains(path) && Catch::Contains(word));
        }
        CHECK(test::fileBytes(path) == before);
        CHECK(dir.entries() == std::vector<std::string>{"frame_0003.exr"});
    }
    CHECK(readFrame(path).get(Channel::Depth).pixels[0] == 2.5f);
}

TEST_CASE("frame reading: missing files, non-EXR files and truncated files name the file", "[frame_io]") {
    TempDir dir;
    const std::string missing = dir.file("nope.exr");
    try {
        readFrame(missing);
        FAIL("expected an error");
    } catch (const hush::Error& e) {
        CHECK(e.kind() == hush::ErrorKind::NotFound);
        CHECK_THAT(e.what(), Catch::Contains(missing) && Catch::Contains("no such file"));
    }

    const std::string text = dir.file("notes.exr");
    std::ofstream(text) << "this is not an image\n";
    CHECK_THROWS_WITH(readFrame(text), Catch::Contains(text) && Catch::Contains("not an OpenEXR file"));
    const std::string emptyFile = dir.file("empty.exr");
    std::ofstream{emptyFile};
    CHECK_THROWS_WITH(readFrame(emptyFile), Catch::Contains(emptyFile) && Catch::Contains("not an OpenEXR file"));
    CHECK_THROWS_WITH(readFrame(dir.path().string()), Catch::Contains(dir.path().string()));

    Frame frame = test::makeFullFrame(64, 48);
    const std::string good = dir.file("good.exr");
    for (ExrCompression compression : {ExrCompression::None, ExrCompression::Zip}) {
        writeFrame(frame, good, {.compression = compression});
        const auto bytes = test::fileBytes(good);
        for (size_t keep : {size_t(8), size_t(100), bytes.size() / 2, bytes.size() - 10, bytes.size() - 1}) {
            INFO("kept " << keep << " of " << bytes.size() << " bytes");
            const std::string cut = dir.file("cut.exr");
            std::ofstream(cut, std::ios::binary).write(bytes.data(), std::streamsize(keep));
            CHECK_THROWS_AS(readFrame(cut), hush::Error);
            CHECK_THROWS_WITH(readFrame(cut), Catch::Contains(cut) && Catch::Contains("damaged or truncated"));
        }
    }
    auto bytes = test::fileBytes(good);   // ZIP data with flipped bits: zlib refuses it
    for (size_t i = bytes.size() / 2; i < bytes.size(); i += 97) bytes[i] = char(bytes[i] ^ 0x5A);
    const std::string corrupt = dir.file("corrupt.exr");
    std::ofstream(corrupt, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    CHECK_THROWS_WITH(readFrame(corrupt), Catch::Contains(corrupt) && Catch::Contains("damaged"));
}

TEST_CASE("frame reading: a header that claims more than the file holds is refused before OpenEXR allocates it",
          "[frame_io]") {
    // Found by tests/fuzz/fuzz_exr_frame: OpenEXR 3.1 allocates and zero-fills what a
    // damaged header claims (1.6 GB for a string in a 973-byte file, seconds of work).
    TempDir dir;
    const std::string good = dir.file("good.exr");
    writeFrame(test::makeFullFrame(8, 4), good);
    const auto bytes = test::fileBytes(good);
    const auto at = [&](const std::string& text) { return std::search(bytes.begin(), bytes.end(), text.begin(), text.end()) - bytes.begin(); };
    const auto patched = [&](const char* name, std::ptrdiff_t offset, std::initializer_list<unsigned char> values) {
        auto copy = bytes;
        std::ptrdiff_t i = offset;
        for (const unsigned char v : values) copy[size_t(i++)] = char(v);
        const std::string path = dir.file(name);
        std::ofstream(path, std::ios::binary).write(copy.data(), std::streamsize(copy.size()));
        return path;
    };
    // The size field of the first string attribute ("hush.scene": name, "string", size).
    const auto scene = at("hush.scene");
    const auto sceneSize = scene + std::ptrdiff_t(std::string("hush.scene").size() + 1 + std::string("string").size() + 1);
    const std::string huge = patched("huge.exr", sceneSize, {0x73, 0x68, 0x2e, 0x63});   // 1.66e9 bytes
    CHECK_THROWS_WITH(readFrame(huge), Catch::Contains(huge) && Catch::Contains("'hush.scene' claims 1663985779 bytes"));
    CHECK_THROWS_WITH(readFrameInfo(huge), Catch::Contains("damaged or truncated"));
    // A data window of 2^31 lines.
    const auto window = at("dataWindow") + std::ptrdiff_t(std::string("dataWindow").size() + 1 + std::string("box2i").size() + 1 + 4);
    const std::string tall = patched("tall.exr", window + 12, {0xff, 0xff, 0xff, 0x7f});
    try {
        readFrame(tall);
        FAIL("expected an error");
    } catch (const hush::Error& e) {
        CHECK(e.kind() == hush::ErrorKind::Unsupported);
        CHECK_THAT(e.what(), Catch::Contains(tall) && Catch::Contains("at most 16384 pixels per side"));
    }
}

TEST_CASE("frame reading: a hush layer with missing or extra components is refused", "[frame_io]") {
    TempDir dir;
    const std::string path = dir.file("frame.exr");
    writeColorFile(path, [](RawExr& exr) {
        exr.addFloat("normal.X", [](int, int) { return 0.0f; });
        exr.addFloat("normal.Y", [](int, int) { return 1.0f; });
    });
    CHECK_THROWS_WITH(readFrame(path), Catch::Contains(path) && Catch::Contains("'normal'") &&
                                           Catch::Contains("(X, Y)") && Catch::Contains("(X, Y, Z)"));
    // Only the layers asked for are checked: the colour alone still loads.
    CHECK(readFrame(path, {.channels = {Channel::Color}}).has(Channel::Color));

    writeColorFile(path, [](RawExr& exr) { exr.addFloat("color.A", [](int, int) { return 1.0f; }); });
    CHECK_THROWS_WITH(readFrame(path), Catch::Contains(path) && Catch::Contains("'color'") &&
                                           Catch::Contains("4 component(s)"));
}

TEST_CASE("frame reading: data windows that are not the whole image or not the expected size", "[frame_io]") {
    TempDir dir;
    const std::string path = dir.file("frame.exr");
    RawExr cropped(13, 7);
    cropped.displayMax[0] = 15;
    cropped.displayMax[1] = 8;
    cropped.addFloat("depth.Z", [](int, int) { return 1.0f; });
    test::writeRawExr(path, cropped);
    CHECK_THROWS_WITH(readFrame(path), Catch::Contains(path) && Catch::Contains("data window (0,0)-(12,6)") &&
                                           Catch::Contains("(0,0)-(15,8)"));

    // A data window away from the origin is fine when it is the display window.
    RawExr offset(13, 7);
    offset.dataMin[0] = offset.displayMin[0] = 10;
    offset.dataMin[1] = offset.displayMin[1] = -3;
    offset.dataMax[0] = offset.displayMax[0] = 22;
    offset.dataMax[1] = offset.displayMax[1] = 3;
    offset.addFloat("depth.Z", [](int x, int y) { return float(x + 100 * y); });
    test::writeRawExr(path, offset);
    const Frame frame = readFrame(path);
    REQUIRE(frame.width == 13);
    CHECK(frame.get(Channel::Depth).at(0, 0)[0] == 0.0f);
    CHECK(frame.get(Channel::Depth).at(12, 6)[0] == 612.0f);
    CHECK_THROWS_WITH(readFrame(path, {.expectedWidth = 13, .expectedHeight = 8}),
                      Catch::Contains(path) && Catch::Contains("13x7") && Catch::Contains("expected 13x8"));
}

TEST_CASE("frame reading: hush attributes of the wrong type and newer versions are refused", "[frame_io]") {
    TempDir dir;
    const std::string path = dir.file("frame.exr");
    writeColorFile(path, [](RawExr& exr) { exr.addStringAttribute("hush.camera.fov", "wide"); });
    try {
        readFrame(path);
        FAIL("expected an error");
    } catch (const hush::Error& e) {
        CHECK(e.kind() == hush::ErrorKind::InvalidArgument);
        CHECK_THAT(e.what(), Catch::Contains(path) && Catch::Contains("'hush.camera.fov'") &&
                                 Catch::Contains("'string'") && Catch::Contains("'float'"));
    }
    writeColorFile(path, [](RawExr& exr) { exr.addFloatAttribute("hush.previousCamera.view", {1, 2, 3}, "v3f"); });
    CHECK_THROWS_WITH(readFrame(path), Catch::Contains("'hush.previousCamera.view'") && Catch::Contains("'m44f'"));
    writeColorFile(path, [](RawExr& exr) { exr.addFloatAttribute("hush.frameIndex", {3.0f}, "float"); });
    CHECK_THROWS_WITH(readFrame(path), Catch::Contains("'hush.frameIndex'") && Catch::Contains("'int'"));
    writeColorFile(path, [](RawExr& exr) { exr.addIntAttribute("hush.frameIndex", -2); });
    CHECK_THROWS_WITH(readFrame(path), Catch::Contains("'hush.frameIndex'") && Catch::Contains("negative"));

    writeColorFile(path, [](RawExr& exr) { exr.addIntAttribute("hush.formatVersion", kFrameFormatVersion + 1); });
    try {
        readFrame(path);
        FAIL("expected an error");
    } catch (const hush::Error& e) {
        CHECK(e.kind() == hush::ErrorKind::Unsupported);
        CHECK_THAT(e.what(), Catch::Contains(path) && Catch::Contains("version"));
    }

    // hush.* names this version does not know are left alone (forward compatibility).
    writeColorFile(path, [](RawExr& exr) { exr.addStringAttribute("hush.somethingNew", "x"); });
    CHECK(readFrame(path).has(Channel::Color));
}
