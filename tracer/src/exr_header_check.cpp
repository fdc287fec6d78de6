// Found by tests/fuzz/fuzz_exr_frame: OpenEXR 3.1 (Debian 12) sizes its buffers by
// what a header claims before it can tell the header is damaged. A string attribute
// claiming 1.6 GB in a 1 KB file is allocated and zero-filled; a channel list is read
// to its terminator whatever its declared size, so the next attribute is read from
// the wrong place; a preview image or a data window of 2^31 lines is allocated too.
// A 1 KB file then costs seconds and gigabytes. This walk reads the header as
// OpenEXR does (the layout is in "The OpenEXR File Layout", openexr.com) and stops
// at the first such claim, before OpenEXR sees the file.
#include <array>
#include <map>
#include <optional>
#include <string_view>

#include "frame_io_detail.hpp"

namespace hush::tracer::detail {

namespace {

// The largest side a frame may have: the renderer's and the GPU textures' limit.
constexpr int64_t kMaxFrameSide = 16384;

// The attribute types OpenEXR reads with a fixed number of bytes, whatever the size
// field says.
const std::map<std::string_view, int32_t>& fixedSizes() {
    static const std::map<std::string_view, int32_t> sizes = {
        {"box2i", 16},   {"box2f", 16},   {"chromaticities", 32}, {"compression", 1}, {"double", 8},
        {"envmap", 1},   {"float", 4},    {"int", 4},             {"keycode", 28},    {"lineOrder", 1},
        {"m33f", 36},    {"m44f", 64},    {"m33d", 72},           {"m44d", 128},      {"rational", 8},
        {"tiledesc", 9}, {"timecode", 8}, {"v2i", 8},             {"v2f", 8},         {"v2d", 16},
        {"v3i", 12},     {"v3f", 12},     {"v3d", 24},            {"deepImageState", 1},
    };
    return sizes;
}

class HeaderWalk {
public:
    HeaderWalk(std::istream& in, std::uintmax_t fileSize, const std::string& prefix)
        : in_(in), fileSize_(fileSize), prefix_(prefix) {}

    // A multi-part file (version flag 0x1000) has one header per part, the list ended
    // by an empty header (a lone null byte); the others have one.
    void run() {
        in_.seekg(4);   // past the magic number
        const bool multipart = (read<int32_t>("the version is cut short") & 0x1000) != 0;
        for (int part = 0;; ++part) {
            if (multipart && part > 0 && in_.peek() == 0) return;
            walkHeader();
            if (!multipart) return;
        }
    }

private:
    void walkHeader() {
        for (;;) {
            const auto name = readName();
            if (!name) damaged("the header does not end");
            if (name->empty()) return;
            const auto type = readName();
            if (!type) damaged("header attribute '" + *name + "' has no type");
            const int32_t size = read<int32_t>("header attribute '" + *name + "' has no size");
            const std::uintmax_t begin = position();
            if (size < 0 || std::uintmax_t(size) > fileSize_ - begin)
                damaged("header attribute '" + *name + "' claims " + std::to_string(size) + " bytes, but only " +
                        std::to_string(fileSize_ - begin) + " remain");
            checkValue(*name, *type, size);
            in_.clear();
            in_.seekg(std::streamoff(begin + std::uintmax_t(size)));
        }
    }

    [[noreturn]] void damaged(const std::string& why) const {
        throw Error(ErrorKind::InvalidArgument, prefix_ + "the file is damaged or truncated (" + why + ")");
    }

    std::uintmax_t position() { return std::uintmax_t(in_.tellg()); }

    template <class T>
    T read(const std::string& what) {
        T value{};
        in_.read(reinterpret_cast<char*>(&value), sizeof value);   // little-endian, as on every machine hush runs on
        if (!in_) damaged(what);
        return value;
    }

    // A null-terminated name of at most 255 characters (OpenEXR's long-name limit),
    // or nullopt at the end of the file.
    std::optional<std::string> readName() {
        std::string name;
        for (char c; in_.get(c);) {
            if (c == '\0') return name;
            if (name.size() == 255) return std::nullopt;
            name.push_back(c);
        }
        return std::nullopt;
    }

    void checkValue(const std::string& name, const std::string& type, int32_t size) {
        const std::string what = "header attribute '" + name + "' (" + type + ")";
        if (const auto fixed = fixedSizes().find(type); fixed != fixedSizes().end() && fixed->second != size)
            damaged(what + " has " + std::to_string(size) + " bytes, not " + std::to_string(fixed->second));
        if (type == "chlist") checkChannelList(what, size);
        if (type == "preview") checkPreview(what, size);
        if (name == "dataWindow" && type == "box2i") checkDataWindow();
    }

    // Entries (name, 16 bytes) up to an empty name, which must end the attribute.
    void checkChannelList(const std::string& what, int32_t size) {
        const std::uintmax_t end = position() + std::uintmax_t(size);
        for (;;) {
            const auto channel = readName();
            if (!channel) damaged(what + " does not end");
            if (channel->empty()) break;
            in_.seekg(16, std::ios::cur);
            if (!in_ || position() > end) damaged(what + " runs past its " + std::to_string(size) + " bytes");
        }
        if (position() != end) damaged(what + " ends before its " + std::to_string(size) + " bytes");
    }

    // Width and height, then 4 bytes per pixel: exactly the attribute's size.
    void checkPreview(const std::string& what, int32_t size) {
        const uint64_t width = read<uint32_t>(what + " is cut short"), height = read<uint32_t>(what + " is cut short");
        if (8 + 4 * width * height != uint64_t(size))
            damaged(what + " claims " + std::to_string(width) + "x" + std::to_string(height) + " pixels in " +
                    std::to_string(size) + " bytes");
    }

    void checkDataWindow() {
        std::array<int32_t, 4> box{};   // xMin, yMin, xMax, yMax
        for (auto& v : box) v = read<int32_t>("the data window is cut short");
        const int64_t width = int64_t(box[2]) - box[0] + 1, height = int64_t(box[3]) - box[1] + 1;
        if (width > kMaxFrameSide || height > kMaxFrameSide)
            throw Error(ErrorKind::Unsupported, prefix_ + "the image is " + std::to_string(width) + "x" +
                                                    std::to_string(height) + "; frames are at most " +
                                                    std::to_string(kMaxFrameSide) + " pixels per side");
    }

    std::istream& in_;
    std::uintmax_t fileSize_;
    const std::string& prefix_;
};

} // namespace

void checkExrHeader(std::istream& in, std::uintmax_t fileSize, const std::string& prefix) {
    HeaderWalk(in, fileSize, prefix).run();
}

} // namespace hush::tracer::detail
