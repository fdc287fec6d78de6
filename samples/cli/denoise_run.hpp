#pragma once
// DenoiseRun: a ChainRunner fed with tracer frames, collecting per-pass GPU times
// over the sequence. `hush denoise` and `hush demo` share it.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <hush/passes/chain_runner.hpp>
#include <hush/tracer/frame.hpp>

#include "display_image.hpp"

namespace hush::cli {

struct DenoisedFrame {
    RgbaImage display;    // tonemapped (+TAA), [0, 1] linear
    RgbaImage radiance;   // filtered HDR radiance
    uint32_t sanitized = 0;   // non-finite input pixels replaced
};

class DenoiseRun {
public:
    // `available`: the channels the frames carry (a chain's optional inputs outside it
    // are not read).
    DenoiseRun(rhi::Device device, std::unique_ptr<passes::Chain> chain, rhi::Extent2D size,
               const std::vector<passes::InputChannel>& available);

    // Throws hush::Error naming the frame and channel when a frame lacks a channel
    // the chain reads, or has another size. A frame without 'emission' has none.
    DenoisedFrame process(const tracer::Frame& frame);
    void resetHistory() { runner_.resetHistory(); }

    const passes::Chain& chain() const { return runner_.chain(); }
    const graph::RenderGraph& graph() const { return runner_.graph(); }
    // GPU ms per pass (execution order) and per frame, one sample per processed frame.
    const std::vector<std::string>& passNames() const { return passNames_; }
    const std::map<std::string, std::vector<double>>& passMs() const { return passMs_; }
    const std::vector<double>& frameMs() const { return frameMs_; }

private:
    passes::ChainRunner runner_;
    std::vector<std::string> passNames_;
    std::map<std::string, std::vector<double>> passMs_;
    std::vector<double> frameMs_;
};


} // namespace hush::cli
