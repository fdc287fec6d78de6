#pragma once
// Frame I/O: one single-part scanline OpenEXR file per frame, layers named
// "<layer>.<component>" after channelInfo(), the cameras in "hush.*" header
// attributes. docs/frame-format.md is the contract; this header is hush's side of it.
#include <cstdint>
#include <string>
#include <vector>

#include <hush/tracer/frame.hpp>

namespace hush::tracer {

// Bumped when a change would make an older hush misread a newer file. Files without
// "hush.formatVersion" (other renderers) are read as version 1.
inline constexpr int kFrameFormatVersion = 1;

enum class ExrCompression : uint8_t {
    None,   // fastest to write, largest files
    Zip,    // lossless, good on smooth G-buffers; the default
    Piz,    // lossless wavelet, usually smaller on noisy 1-spp colour
};

struct WriteOptions {
    ExrCompression compression = ExrCompression::Zip;
    // Store the channels that default to half (ChannelInfo::storedAs) as 32-bit float,
    // for bit-exact round trips. meshid stays UINT either way.
    bool allFloat = false;
};

struct ReadOptions {
    std::vector<Channel> channels;   // which layers to load; empty: every hush layer present
    // A layer named in `channels` but absent from the file throws (a chain asked for it);
    // false: it is simply left out of the frame.
    bool requireChannels = true;
    // Non-zero: the image must be exactly this size (a sequence must not change size).
    uint32_t expectedWidth = 0;
    uint32_t expectedHeight = 0;
};

// Writes `frame` to `path` atomically: the data go to "<path>.tmp-<pid>" in the same
// folder, which is renamed over `path` only once complete. On any failure the
// temporary is removed, an existing `path` is untouched, and hush::Error names `path`.
// The folder must exist. Two threads of one process must not write the same path at
// once (they would share the temporary's name).
// Finite values beyond half's range in a half channel are clamped to +-65504 (not
// turned into infinities); NaN and +-Inf are kept.
void writeFrame(const Frame& frame, const std::string& path, const WriteOptions& options = {});

// Reads a frame written by hush or by any renderer that follows docs/frame-format.md,
// or a Blender Cycles multilayer file (its passes mapped onto hush's layers,
// docs/blender.md).
// Throws hush::Error naming the file: missing, not OpenEXR, truncated, a hush layer
// with missing or extra components, a data window that is not the display window or
// not the expected size, a known "hush.*" attribute of the wrong type.
Frame readFrame(const std::string& path, const ReadOptions& options = {});

// What a frame file holds, from its header alone (no pixels read): for tools and tests.
struct FrameFileInfo {
    uint32_t width = 0;
    uint32_t height = 0;
    std::string compression;   // "none", "zip", "piz", or another EXR codec's name
    struct ExrChannel {
        std::string name;   // "color.R"
        PixelKind type;
    };
    std::vector<ExrChannel> exrChannels;   // every channel in the file, sorted by name
    std::vector<Channel> layers;           // the hush layers among them (complete or not); for a Blender
                                           // Cycles file, those readFrame makes from its passes
};
FrameFileInfo readFrameInfo(const std::string& path);

// Worker threads OpenEXR uses to (de)compress frames, process-wide (OpenEXR keeps one
// pool). 0, the default, compresses on the calling thread. Applications that write
// many frames (the CLI) raise it; a library linking hush is not changed behind its back.
void setFrameIoThreadCount(unsigned threads);

// Sequences: frame i of a folder is "<folder>/frame_<i>.exr", i zero-padded to at
// least 4 digits (frame_0000.exr, ..., frame_9999.exr, frame_10000.exr).
std::string framePath(const std::string& folder, uint32_t index);
// The frame files of `folder` sorted by index (any number of digits). Throws
// hush::Error if the folder is missing, holds no frame file, or holds two files for
// one index (frame_7.exr and frame_0007.exr).
std::vector<std::string> listFrames(const std::string& folder);

// meshid between memory and disk (frame.hpp): in the Image the id as a float value
// (exact below 2^24) or kNoMesh (-1); in the file UINT, kNoMeshOnDisk for no hit.
float meshIdToPixel(uint32_t id);      // kNoMeshOnDisk -> kNoMesh
// Negative (kNoMesh), NaN and values >= 2^32-1 -> kNoMeshOnDisk; others truncate
// towards zero.
uint32_t meshIdFromPixel(float value);

} // namespace hush::tracer
