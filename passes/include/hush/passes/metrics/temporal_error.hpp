#pragma once
// Temporal error (Schied et al. 2017, SVGF, Sec. 5.4 and Fig. 10): "the average
// luminance of the per-pixel differences" between consecutive frames, here
//   mean over pixels of dot(|current - previous|, (0.2126, 0.7152, 0.0722))
// i.e. the Rec. 709 luminance of the absolute RGB difference (the paper names
// neither the absolute value nor the weights; docs/passes/metrics.md says why these).
// A pixel with a non-finite RGB component in either frame is left out and counted.
#include <cstdint>
#include <span>
#include <string>

#include <hush/passes/node_context.hpp>

namespace hush::passes {

// Rec. 709 / sRGB primaries' luminance weights.
inline constexpr float kRec709Luminance[3] = {0.2126f, 0.7152f, 0.0722f};

// Adds the pass "<name>": both frames any float format at output size. Returns the
// partial sums (per workgroup: luminance sum, finite pixels, non-finite pixels, 0),
// marked as an output.
graph::BufferHandle addTemporalErrorPass(NodeContext& ctx, const std::string& name, graph::TextureHandle current,
                                         graph::TextureHandle previous);

struct TemporalError {
    double error = 0.0;
    uint64_t pixels = 0;            // the finite pixels the mean is over
    uint64_t nonFinitePixels = 0;   // left out
};

// The temporal error from read-back partials. Throws hush::Error (InvalidArgument)
// when no pixel is finite or the sum overflowed.
TemporalError temporalErrorFromPartials(std::span<const float> partials);

} // namespace hush::passes
