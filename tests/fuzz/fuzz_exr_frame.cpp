// libFuzzer harness for the EXR frame reader (tracer/src/frame_io_read.cpp):
// any file must read into a consistent frame or throw hush::Error. readFrameInfo
// (the header alone) must agree with the full read on the size. Pixels are read only
// for headers of at most 64K pixels: a mutated header easily claims 16384x16384,
// and zero-filling gigabytes per input would leave no time for anything else (the
// size limit itself is tested in tests/tracer/test_frame_io_errors.cpp).
#include <cstddef>
#include <cstdint>

#include <hush/core/error.hpp>
#include <hush/tracer/frame_io.hpp>

#include "fuzz_replay.hpp"
#include "fuzz_require.hpp"
#include "fuzz_scratch.hpp"

using namespace hush::tracer;

namespace {

void checkFrame(const Frame& frame) {
    const std::size_t pixels = std::size_t(frame.width) * frame.height;
    hush::fuzz::require(frame.width > 0 && frame.height > 0);
    for (const auto& [channel, image] : frame.channels) {
        hush::fuzz::require(image.width == frame.width && image.height == frame.height);
        hush::fuzz::require(image.channels == channelInfo(channel).components);
        hush::fuzz::require(image.pixels.size() == pixels * image.channels);
    }
}

} // namespace

int hush::fuzz::exrFrame(const std::uint8_t* data, std::size_t size) {
    const std::string path = hush::fuzz::writeScratch("frame_0000.exr", data, size);
    uint32_t headerWidth = 0, headerHeight = 0;
    try {
        const FrameFileInfo info = readFrameInfo(path);
        headerWidth = info.width;
        headerHeight = info.height;
    } catch (const hush::Error&) {
    }
    if (uint64_t(headerWidth) * headerHeight > 65536) return 0;
    try {
        const Frame frame = readFrame(path);
        checkFrame(frame);
        hush::fuzz::require(frame.width == headerWidth && frame.height == headerHeight);
    } catch (const hush::Error&) {
    }
    return 0;
}

HUSH_FUZZ_TARGET(hush::fuzz::exrFrame)
