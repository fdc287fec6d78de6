#pragma once
// Temporal anti-aliasing (Karis 2014, "High Quality Temporal Supersampling",
// SIGGRAPH Advances in Real-Time Rendering course), on display (tonemapped) values.
// Per pixel p (centre p + 0.5):
//   1. history: last frame's TAA output, fetched bilinearly (edge texels repeat) at
//      p + 0.5 + motion(p), motion = previous minus current pixel position, in pixels.
//      A position outside [0, width) x [0, height) has no history.
//   2. rectification: a box in YCoCg around the 3x3 neighbourhood of the current
//      frame, either its min/max (Karis 2014) or mean +- gamma * stddev (variance
//      clipping, Salvi 2016, "An Excursion in Temporal Supersampling", GDC); the
//      history is clamped to the box per component, or clipped along the segment
//      from the box centre to the history ("neighbourhood clipping", Karis 2014).
//   3. output = lerp(history', current, alpha) (exponential moving average), negative
//      components (a YCoCg box corner need not be a valid RGB colour) set to 0.
// Without history (first frame, after resetHistory(), out-of-screen motion) the
// output is the current colour. Output alpha is 1.
#include <cstdint>
#include <string>

#include <hush/passes/node_context.hpp>

namespace hush::passes {

enum class TaaBox : uint32_t {
    MinMax = 0,     // per-component min and max of the 3x3 neighbourhood (Karis 2014)
    Variance = 1,   // mean +- gamma * stddev of the 3x3 neighbourhood (Salvi 2016)
};

enum class TaaRectify : uint32_t {
    Clamp = 0,   // clamp each YCoCg component of the history to the box
    Clip = 1,    // move the history towards the box centre until it is inside (Karis 2014)
};

struct TaaSettings {
    float alpha = 0.1f;                      // weight of the current frame (Karis 2014: 0.1)
    TaaBox box = TaaBox::MinMax;             // Karis 2014
    TaaRectify rectify = TaaRectify::Clip;   // Karis 2014
    float varianceGamma = 1.0f;              // box half-size in stddevs, TaaBox::Variance only (Salvi 2016: about 1)
};

// Adds pass "<name>". `current`: rgba (rgb used); `motion`: rg, in pixels (any float
// formats, full output size). Returns the anti-aliased colour, rgba32f transient
// "<name>"; its last-frame value (graph.history("<name>", ...)) is the TAA history.
graph::TextureHandle addTaaPass(NodeContext& ctx, const std::string& name, graph::TextureHandle current,
                                graph::TextureHandle motion, const TaaSettings& settings = {});

} // namespace hush::passes
