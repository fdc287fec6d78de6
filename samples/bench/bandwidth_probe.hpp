#pragma once
// One bandwidth measurement: a copy kernel (or host memcpy) run repeatedly over
// one resource kind and size, timed per run, with its result verified.
#include <cstdint>
#include <string>
#include <vector>

#include <hush/rhi/device.hpp>

namespace hush::bench {

enum class ProbeKind : uint8_t { Texture, Buffer, HostMemcpy };

struct ProbeCase {
    std::string kernel;          // "texture rgba16f", "buffer vec4", "host memcpy"
    ProbeKind kind = ProbeKind::Texture;
    rhi::Format format = rhi::Format::Undefined;   // Texture only
    rhi::Extent2D size;
    uint32_t bytesPerPixel = 0;  // read once and written once per pixel
    uint64_t bytes() const { return uint64_t(size.width) * size.height * bytesPerPixel; }
};

struct ProbeTimings {
    std::vector<double> ms;      // one per measured run (warm-up runs excluded)
    std::string timer;           // "gpu-timestamps", "host-submit-wait" or "host-clock"
    bool verified = false;       // the destination held an exact copy afterwards
};

// Runs `warmup` untimed then `runs` timed copies on the device. Throws hush::Error
// when the device cannot (unsupported format, buffer larger than a binding, ...).
ProbeTimings runDeviceProbe(const rhi::Device& device, const ProbeCase& probe, uint32_t warmup,
                            uint32_t runs);

// The same byte count copied with std::memcpy on the host.
ProbeTimings runHostProbe(const ProbeCase& probe, uint32_t warmup, uint32_t runs);

} // namespace hush::bench
