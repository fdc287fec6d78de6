#pragma once
// Helpers for the frame I/O tests: a scratch folder, a frame with every channel, and
// a from-scratch OpenEXR writer. The raw writer follows the published file layout
// (magic, header attributes, offset table, uncompressed scanline chunks) and shares
// no code with hush or OpenEXR, so files it makes stand in for another renderer's,
// and it can make the malformed files hush must reject.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <hush/tracer/frame.hpp>

namespace hush::tracer::test {

namespace fs = std::filesystem;

// A fresh folder under the system temp dir, removed with everything in it at the end.
class TempDir {
public:
    TempDir() {
        static int counter = 0;
        path_ = fs::temp_directory_path() /
                ("hush-frameio-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    const fs::path& path() const { return path_; }
    std::vector<std::string> entries() const {   // names directly inside, sorted
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(path_)) names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    fs::path path_;
};

// A deterministic value in [-range, range) from a pixel and a seed (integer hash).
inline float hashValue(uint32_t a, uint32_t b, float range) {
    uint32_t h = a * 0x9E3779B1u ^ (b + 0x7F4A7C15u);
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    return (float(h >> 8) / float(1u << 24) * 2.0f - 1.0f) * range;
}

inline CameraInfo testCamera(float seed) {
    CameraInfo camera;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            camera.view[i][j] = seed + 0.1f * float(i * 4 + j) + 1e-7f;
            camera.projection[i][j] = -seed * float(i + 1) / float(j + 3);
        }
    camera.jitter = {0.25f * seed, -0.375f};
    camera.position = {seed, 2.5f, -3.125f};
    camera.verticalFovDegrees = 47.3f + seed;
    camera.nearPlane = 0.013f;
    camera.farPlane = 777.7f;
    return camera;
}

// Every channel filled with hashed values (meshid with small ids and kNoMesh).
inline Frame makeFullFrame(uint32_t width, uint32_t height) {
    Frame frame;
    frame.width = width;
    frame.height = height;
    frame.index = 42;
    frame.scene = "cornell box \"test\"";
    frame.referenceSpp = 1024;
    frame.camera = testCamera(1.5f);
    frame.previousCamera = testCamera(-0.75f);
    for (Channel channel : kAllChannels) {
        Image& image = frame.add(channel);
        for (size_t i = 0; i < image.pixels.size(); ++i)
            image.pixels[i] = channel == Channel::MeshId ? (i % 5 == 4 ? kNoMesh : float(i % 7))
                                                         : hashValue(uint32_t(i), uint32_t(channel), 100.0f);
    }
    return frame;
}

// ---- a minimal OpenEXR writer: single part, scanline, no compression ----

inline constexpr int kRawUint = 0, kRawHalf = 1, kRawFloat = 2;

struct RawChannel {
    std::string name;
    int type = kRawFloat;          // kRawUint or kRawFloat (4-byte types only)
    std::vector<uint32_t> words;   // one per data-window pixel, row-major from the top
};

struct RawAttribute {
    std::string name, type;
    std::vector<uint8_t> bytes;
};

struct RawExr {
    int dataMin[2] = {0, 0}, dataMax[2] = {0, 0};
    int displayMin[2] = {0, 0}, displayMax[2] = {0, 0};
    std::vector<RawChannel> channels;
    std::vector<RawAttribute> attributes;

    RawExr(int width, int height) : dataMax{width - 1, height - 1}, displayMax{width - 1, height - 1} {}
    int width() const { return dataMax[0] - dataMin[0] + 1; }
    int height() const { return dataMax[1] - dataMin[1] + 1; }

    template <class F> void addFloat(const std::string& name, F valueAt) {   // valueAt(x, y)
        RawChannel channel{name, kRawFloat, {}};
        for (int y = 0; y < height(); ++y)
            for (int x = 0; x < width(); ++x) channel.words.push_back(std::bit_cast<uint32_t>(float(valueAt(x, y))));
        channels.push_back(std::move(channel));
    }
    void addUint(const std::string& name, std::vector<uint32_t> values) {
        channels.push_back({name, kRawUint, std::move(values)});
    }
    void addFloatAttribute(const std::string& name, const std::vector<float>& values, const std::string& type) {
        RawAttribute attribute{name, type, {}};
        for (float v : values)
            for (int b = 0; b < 4; ++b) attribute.bytes.push_back(uint8_t(std::bit_cast<uint32_t>(v) >> (8 * b)));
        attributes.push_back(std::move(attribute));
    }
    void addIntAttribute(const std::string& name, int32_t value) {
        RawAttribute attribute{name, "int", {}};
        for (int b = 0; b < 4; ++b) attribute.bytes.push_back(uint8_t(uint32_t(value) >> (8 * b)));
        attributes.push_back(std::move(attribute));
    }
    void addStringAttribute(const std::string& name, const std::string& value) {
        attributes.push_back({name, "string", std::vector<uint8_t>(value.begin(), value.end())});
    }
};

namespace raw_detail {
inline void put32(std::vector<uint8_t>& out, uint32_t v) {
    for (int b = 0; b < 4; ++b) out.push_back(uint8_t(v >> (8 * b)));   // EXR is little-endian
}
inline void putString(std::vector<uint8_t>& out, const std::string& s) {
    out.insert(out.end(), s.begin(), s.end());
    out.push_back(0);
}
inline void putAttribute(std::vector<uint8_t>& out, const std::string& name, const std::string& type,
                         const std::vector<uint8_t>& bytes) {
    putString(out, name);
    putString(out, type);
    put32(out, uint32_t(bytes.size()));
    out.insert(out.end(), bytes.begin(), bytes.end());
}
inline std::vector<uint8_t> box(const int min[2], const int max[2]) {
    std::vector<uint8_t> out;
    for (int v : {min[0], min[1], max[0], max[1]}) put32(out, uint32_t(v));
    return out;
}
} // namespace raw_detail

inline void writeRawExr(const std::string& path, RawExr exr) {
    using namespace raw_detail;
    std::sort(exr.channels.begin(), exr.channels.end(),
              [](const RawChannel& a, const RawChannel& b) { return a.name < b.name; });   // the format wants this
    std::vector<uint8_t> out = {0x76, 0x2f, 0x31, 0x01};   // magic
    put32(out, 2);                                          // version 2, single-part scanline
    std::vector<uint8_t> channelList;
    for (const auto& channel : exr.channels) {
        putString(channelList, channel.name);
        put32(channelList, uint32_t(channel.type));
        put32(channelList, 0);   // pLinear + 3 reserved bytes
        put32(channelList, 1);   // xSampling
        put32(channelList, 1);   // ySampling
    }
    channelList.push_back(0);
    putAttribute(out, "channels", "chlist", channelList);
    putAttribute(out, "compression", "compression", {0});
    putAttribute(out, "dataWindow", "box2i", box(exr.dataMin, exr.dataMax));
    putAttribute(out, "displayWindow", "box2i", box(exr.displayMin, exr.displayMax));
    putAttribute(out, "lineOrder", "lineOrder", {0});
    std::vector<uint8_t> one, center;
    put32(one, std::bit_cast<uint32_t>(1.0f));
    put32(center, 0);
    put32(center, 0);
    putAttribute(out, "pixelAspectRatio", "float", one);
    putAttribute(out, "screenWindowCenter", "v2f", center);
    putAttribute(out, "screenWindowWidth", "float", one);
    for (const auto& attribute : exr.attributes) putAttribute(out, attribute.name, attribute.type, attribute.bytes);
    out.push_back(0);   // end of header

    // Offset table (one chunk per scanline without compression), then the chunks.
    const size_t lineBytes = exr.channels.size() * size_t(exr.width()) * 4;
    const size_t tableStart = out.size();
    out.resize(out.size() + 8 * size_t(exr.height()));
    for (int row = 0; row < exr.height(); ++row) {
        const uint64_t offset = out.size();
        for (int b = 0; b < 8; ++b) out[tableStart + 8 * size_t(row) + size_t(b)] = uint8_t(offset >> (8 * b));
        put32(out, uint32_t(exr.dataMin[1] + row));
        put32(out, uint32_t(lineBytes));
        for (const auto& channel : exr.channels)
            for (int x = 0; x < exr.width(); ++x)
                put32(out, channel.words[size_t(row) * size_t(exr.width()) + size_t(x)]);
    }
    std::ofstream file(path, std::ios::binary);
    file.write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
}

inline std::vector<char> fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace hush::tracer::test
