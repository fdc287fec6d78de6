#pragma once
// The render-graph self-check of `hush info`: a five-pass graph (one pass to be
// culled, one reading a history) run for a few frames, its output compared with
// the same arithmetic on the CPU.
#include <cstdint>
#include <string>
#include <vector>

#include <hush/rhi/device.hpp>

namespace hush::cli {

struct GraphSelfCheckResult {
    uint32_t frames = 0;
    double maxError = 0.0;                 // absolute, over every frame's output
    double tolerance = 0.0;
    std::vector<std::string> culled;       // expected: exactly the unused pass
    uint32_t compiles = 0;                 // expected: 1
    double totalGpuMs = 0.0;               // of the last frame, when timed
    bool timed = false;
    std::string dot, json;                 // the compiled graph, for --dump-graph
    bool passed() const;
};

GraphSelfCheckResult runGraphSelfCheck(const rhi::Device& device);

} // namespace hush::cli
