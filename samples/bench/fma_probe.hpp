#pragma once
// The compute roofline: multiply-add throughput of the device (shaders/bench/fma.comp),
// what a convolution's arithmetic is measured against, as the copy probe's
// bandwidth is for a pass's bytes.
#include <cstdint>
#include <string>
#include <vector>

#include <hush/rhi/device.hpp>

namespace hush::bench {

struct FmaTimings {
    uint64_t flops = 0;          // per run (a multiply-add counts 2)
    std::vector<double> ms;      // per timed run
    std::string timer;
    bool verified = false;       // every invocation's sum is the closed-form value
};

// Sizes the work (doubling the iterations) until one run takes at least `minMs`, then
// times `runs` runs after `warmup`.
FmaTimings runFmaProbe(const rhi::Device& device, uint32_t warmup, uint32_t runs, double minMs = 20.0);

} // namespace hush::bench
