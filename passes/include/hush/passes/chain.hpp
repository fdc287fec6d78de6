#pragma once
// A chain: a whole denoiser composed of nodes (SvgfChain, EawChain, a chain loaded
// from a JSON file). It adds its passes to a graph, reading a frame's inputs, and
// marks what it produces as outputs.
#include <string>
#include <vector>

#include <hush/passes/denoise_inputs.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

struct ChainOutputs {
    // What a user sees: tonemapped (and anti-aliased), rgba32f in [0, 1], linear
    // (encode to sRGB for an 8-bit file).
    graph::TextureHandle display;
    // Filtered HDR radiance before tonemapping (remodulated), rgba32f.
    graph::TextureHandle radiance;
    // Non-finite input pixels replaced this frame, one uint per InputChannel.
    graph::BufferHandle sanitizeCounts;
};

class Chain {
public:
    virtual ~Chain() = default;
    virtual std::string name() const = 0;                     // "svgf"
    virtual std::vector<InputChannel> inputs() const = 0;     // the channels build() reads
    // Channels build() reads when the frames have them and does without otherwise
    // (Mara's glossy term: without it, the glossy branch is culled).
    virtual std::vector<InputChannel> optionalInputs() const { return {}; }
    // Adds the chain's passes to ctx.graph and marks display, radiance and
    // sanitizeCounts as outputs. `inputs` holds at least the channels of inputs().
    virtual ChainOutputs build(NodeContext& ctx, const DenoiseInputs& inputs) = 0;
};

} // namespace hush::passes
