// libFuzzer harness for the BMFR dataset reader (tracer/src/bmfr_dataset.cpp).
// The first byte picks what the rest of the input is: even, the camera text file;
// odd, color0.exr in a folder whose other files (normal, position, albedo) are
// valid 4x4 images written once. Either must read or throw hush::Error. As in
// fuzz_exr_frame.cpp, pixels are read only for headers of at most 64K pixels.
#include <cstddef>
#include <cstdint>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <vector>

#include <hush/core/error.hpp>
#include <hush/tracer/bmfr_dataset.hpp>
#include <hush/tracer/frame_io.hpp>

#include "fuzz_replay.hpp"
#include "fuzz_require.hpp"
#include "fuzz_scratch.hpp"

using namespace hush::tracer;

namespace {

// One of the dataset's files as their renderer writes it: float "R", "G", "B".
void writeBmfrStyleImage(const std::string& path, int width, int height, float value) {
    Imf::Header header(width, height);
    for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    std::vector<float> pixels(std::size_t(width) * height, value);
    Imf::FrameBuffer buffer;
    for (const char* name : {"R", "G", "B"})
        buffer.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data()), sizeof(float), sizeof(float) * width));
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(buffer);
    file.writePixels(height);
}

// False when the file's header claims more than 64K pixels. Read through hush's own
// header check (readFrameInfo), never by opening the input with OpenEXR here: that
// would make the harness allocate whatever a damaged header claims.
bool smallEnough(const std::string& path) {
    try {
        const FrameFileInfo info = readFrameInfo(path);
        return uint64_t(info.width) * info.height <= 65536;
    } catch (const hush::Error&) {
        return true;   // then the reader must refuse it as well
    }
}

void writeCompanionFiles() {
    static bool written = false;
    if (written) return;
    for (const char* name : {"shading_normal0.exr", "world_position0.exr", "albedo0.exr"})
        writeBmfrStyleImage((hush::fuzz::scratchFolder() / name).string(), 4, 4, 0.5f);
    written = true;
}

} // namespace

int hush::fuzz::bmfrDataset(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    writeCompanionFiles();
    const bool image = (data[0] & 1) != 0;
    try {
        if (!image) {
            const std::string path = hush::fuzz::writeScratch("camera.txt", data + 1, size - 1);
            const BmfrCameraData camera = readBmfrCameraFile(path);
            hush::fuzz::require(camera.jitter.size() == camera.viewProjection.size());
        } else {
            const std::string path = hush::fuzz::writeScratch("color0.exr", data + 1, size - 1);
            if (!smallEnough(path)) return 0;
            const Frame frame = readBmfrFrame(hush::fuzz::scratchFolder().string(), 0);
            hush::fuzz::require(frame.width == 4 && frame.height == 4);
            hush::fuzz::require(frame.get(Channel::Color).pixels.size() == 4 * 4 * 3);
        }
    } catch (const hush::Error&) {
    }
    return 0;
}

HUSH_FUZZ_TARGET(hush::fuzz::bmfrDataset)
