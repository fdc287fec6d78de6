#pragma once
// BMFR's temporal accumulation (Koskela et al. 2019, Sec. 3.1 for the noisy input,
// Sec. 3.3 for the fitted output): last frame's value of this node, read through the
// shared reprojection decision (common/reproject.hpp: bilinear taps with per-tap
// discard, weights renormalised over the accepted taps), is blended with the new
// sample by a cumulative moving average until the new sample's weight would fall
// below `minWeight`, then by an exponential moving average with that weight:
//
//   n_prev = round(sum_k w_k * count_k)          (Sec. 3.1: "the sample count data is
//                                                   sampled using the same custom bilinear
//                                                   sampling and ... rounded")
//   n      = disoccluded ? 1 : min(n_prev + 1, N),  N = ceil(1 / minWeight)
//   a      = max(minWeight, 1 / n)
//   out    = a * x + (1 - a) * sum_k w_k * out_prev_k
//
// The count saturates at N, where 1 / N <= minWeight and the blend no longer changes
// (Sec. 3.1: "we are interested in the sample count only if the count is small").
// A disocclusion, the first frame and resetHistory() restart the count at 1.
//
// The decision is an input, not made here: the post-accumulation reuses the first
// stage's decision texture (Sec. 3.3: "reusing the motion vectors and discard
// decisions from the preprocessing phase").
#include <string>

#include <hush/passes/settings.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

struct BmfrAccumulateSettings {
    // The smallest weight of the new sample. Sec. 3.1: 0.2 for the noisy input ("mix
    // 80% of the history data with 20% of the current frame data"); Sec. 3.3: 0.1 for
    // the fitted frames ("10% of new data and 90% old data"). In (0, 1]; 1 keeps no
    // history.
    float minWeight = 0.2f;
    // Format of the output and its history: RGBA32Float (default) or RGBA16Float
    // (BmfrSettings::halfPrecision; values clamped to +-65504, the largest finite half).
    rhi::Format format = rhi::Format::RGBA32Float;
};

template <class V> void describe(V&& v, BmfrAccumulateSettings& s) {
    v.field("minWeight", s.minWeight, Range{1e-6, 1.0});
    v.field("format", s.format, kStorageFormatNames);
}

// Sec. 3.3's setting for the accumulation after the fit.
inline BmfrAccumulateSettings bmfrPostAccumulateSettings() { return {.minWeight = 0.1f}; }

// The sample count at which the blend becomes exponential: ceil(1 / minWeight).
// Throws hush::Error (InvalidArgument) unless 0 < minWeight <= 1 and the format is
// RGBA32Float or RGBA16Float.
uint32_t bmfrAccumulateCountCap(const BmfrAccumulateSettings& settings);

// Adds pass "<name>": transient "<name>" in settings.format (rgba32f by default), rgb the accumulated input, alpha the
// per-pixel sample count n (an integer in [1, N]). Its history is itself
// (graph.history(name)). `input` is read as rgb (any float format); `reprojection`
// is addReprojectPass's decision. Throws hush::Error (InvalidArgument) on a bad
// minWeight or format.
graph::TextureHandle addBmfrAccumulatePass(NodeContext& ctx, const std::string& name, graph::TextureHandle current,
                                           graph::TextureHandle reprojection,
                                           const BmfrAccumulateSettings& settings = {});

} // namespace hush::passes
