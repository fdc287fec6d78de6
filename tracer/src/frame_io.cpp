// Frame sequences (file naming, listing), the meshid float mapping, and the small
// helpers the EXR reader, writer and BMFR reader share.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <utility>

#include <OpenEXR/ImfThreading.h>
#include <OpenEXR/ImfVersion.h>

#include <hush/tracer/frame_io.hpp>

#include "frame_io_detail.hpp"

namespace hush::tracer {

namespace fs = std::filesystem;

std::string framePath(const std::string& folder, uint32_t index) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04u.exr", unsigned(index));
    return (fs::path(folder) / name).string();
}

std::vector<std::string> listFrames(const std::string& folder) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        throw Error(ErrorKind::NotFound, "frame folder '" + folder + "' does not exist or is not a folder");
    std::vector<std::pair<long long, std::string>> frames;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
        if (!entry.is_regular_file(ec)) continue;
        const std::string name = entry.path().filename().string();
        const long long index = detail::frameIndexFromFileName(name);
        if (index >= 0) frames.emplace_back(index, entry.path().string());
    }
    if (ec) throw Error(ErrorKind::NotFound, "cannot list frame folder '" + folder + "': " + ec.message());
    if (frames.empty())
        throw Error(ErrorKind::NotFound,
                    "no frames in '" + folder + "': expected files named frame_<N>.exr (frame_0000.exr, ...)");
    std::sort(frames.begin(), frames.end());
    for (size_t i = 1; i < frames.size(); ++i)
        if (frames[i].first == frames[i - 1].first)
            throw Error(ErrorKind::InvalidArgument, "two files for frame " + std::to_string(frames[i].first) +
                                                        " in '" + folder + "': '" + frames[i - 1].second +
                                                        "' and '" + frames[i].second + "'");
    std::vector<std::string> paths;
    paths.reserve(frames.size());
    for (auto& frame : frames) paths.push_back(std::move(frame.second));
    return paths;
}

void setFrameIoThreadCount(unsigned threads) {
    Imf::setGlobalThreadCount(int(std::min(threads, 256u)));
}

float meshIdToPixel(uint32_t id) { return id == kNoMeshOnDisk ? kNoMesh : static_cast<float>(id); }

uint32_t meshIdFromPixel(float value) {
    // The conversion to uint32_t is undefined outside [0, 2^32): route those (and NaN)
    // to "no hit" first. float(0xFFFFFFFF) rounds to 2^32, so it lands there too.
    if (!(value >= 0.0f) || value >= 4294967295.0f) return kNoMeshOnDisk;
    return static_cast<uint32_t>(value);
}

namespace detail {

void checkExrFile(const std::string& path, std::string_view what) {
    const std::string prefix = "cannot read " + std::string(what) + " '" + path + "': ";
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (!fs::exists(status)) throw Error(ErrorKind::NotFound, prefix + "no such file");
    if (!fs::is_regular_file(status)) throw Error(ErrorKind::InvalidArgument, prefix + "not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(ErrorKind::NotFound, prefix + "the file cannot be opened");
    std::array<char, 4> magic{};
    in.read(magic.data(), magic.size());
    if (in.gcount() != 4 || !Imf::isImfMagic(magic.data()))
        throw Error(ErrorKind::InvalidArgument,
                    prefix + "not an OpenEXR file (it does not start with the OpenEXR magic number)");
    checkExrHeader(in, fs::file_size(path, ec), prefix);
}

std::string boxText(const Imath::Box2i& box) {
    char text[96];
    std::snprintf(text, sizeof text, "(%d,%d)-(%d,%d)", box.min.x, box.min.y, box.max.x, box.max.y);
    return text;
}

std::string compressionName(Imf::Compression compression) {
    switch (compression) {
    case Imf::NO_COMPRESSION: return "none";
    case Imf::RLE_COMPRESSION: return "rle";
    case Imf::ZIPS_COMPRESSION: return "zips";
    case Imf::ZIP_COMPRESSION: return "zip";
    case Imf::PIZ_COMPRESSION: return "piz";
    case Imf::PXR24_COMPRESSION: return "pxr24";
    case Imf::B44_COMPRESSION: return "b44";
    case Imf::B44A_COMPRESSION: return "b44a";
    case Imf::DWAA_COMPRESSION: return "dwaa";
    case Imf::DWAB_COMPRESSION: return "dwab";
    default: return "unknown";
    }
}

long long frameIndexFromFileName(std::string_view name) {
    constexpr std::string_view prefix = "frame_", suffix = ".exr";
    if (name.size() <= prefix.size() + suffix.size() || name.substr(0, prefix.size()) != prefix ||
        name.substr(name.size() - suffix.size()) != suffix)
        return -1;
    const std::string_view digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    long long index = 0;
    for (char c : digits) {
        if (c < '0' || c > '9') return -1;
        index = index * 10 + (c - '0');
        if (index > 0xFFFFFFFFll) return -1;   // also stops overflow on absurdly long names
    }
    return index;
}

} // namespace detail
} // namespace hush::tracer
