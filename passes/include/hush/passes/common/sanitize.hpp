#pragma once
// Sanitise a frame's inputs: the first node of every chain. NaN and Inf become a
// per-channel replacement (0; -1 for meshid), values are clamped to the channel's
// valid range (radiance to [0, maxRadiance], albedo to [0, 1]), and the pixels
// that held a non-finite value are counted per channel, for diagnostics.
#include <string>

#include <hush/passes/settings.hpp>
#include <hush/passes/denoise_inputs.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

struct SanitizeSettings {
    // Radiance above this is clamped: its square (luminance moments) must stay
    // finite in fp32. Far above any real radiance (1e6 fireflies pass unchanged).
    float maxRadiance = 1e8f;
};

template <class V> void describe(V&& v, SanitizeSettings& s) { v.field("maxRadiance", s.maxRadiance, Range{1.0, 1e30}); }

struct SanitizedInputs {
    DenoiseInputs inputs;         // the sanitised channels: transients "<name>.<channel>"
    graph::BufferHandle counts;   // kInputChannelCount uints, by InputChannel: pixels replaced this frame
};

// Adds "<name>.clear" and one "<name>.<channel>" pass per valid input. The counts
// buffer is marked as an output, so RenderGraph::outputBuffer reads it back.
SanitizedInputs addSanitizePass(NodeContext& ctx, const std::string& name, const DenoiseInputs& inputs,
                                const SanitizeSettings& settings = {});

// The range a channel is clamped to and what replaces its non-finite components.
struct SanitizeRange {
    float lo, hi, replacement;
};
SanitizeRange sanitizeRange(InputChannel channel, const SanitizeSettings& settings = {});

} // namespace hush::passes
