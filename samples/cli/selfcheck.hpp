#pragma once
// The compute self-check of `hush info`: one dispatch of shaders/rhi/selfcheck.comp
// (saxpy on storage buffers plus a read-write RGBA32F storage image) compared with
// the same computation on the CPU.
#include <cstdint>
#include <optional>

#include <hush/rhi/device.hpp>

namespace hush::cli {

struct SelfCheckResult {
    uint32_t width = 0;             // of the image; the saxpy covers width * height
    uint32_t height = 0;
    double bufferMaxError = 0.0;    // relative: |gpu - cpu| / max(1, |cpu|)
    double imageMaxError = 0.0;
    double tolerance = 0.0;
    std::optional<double> gpuMs;    // from timestamps, when the adapter has them
    bool passed() const;
};

// Throws hush::Error when the device cannot run the check at all.
SelfCheckResult runSelfCheck(const rhi::Device& device);

} // namespace hush::cli
