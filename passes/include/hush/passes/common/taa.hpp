#pragma once
// Temporal anti-aliasing (Karis 2014, "High Quality Temporal Supersampling",
// SIGGRAPH Advances in Real-Time Rendering course), on display (tonemapped) values.
// Per pixel p (centre p + 0.5):
//   1. history: last frame's TAA output at p + 0.5 + motion(p), motion = previous
//      minus current pixel position, in pixels, resampled with
//      TaaSettings::historyFilter (edge texels repeat). A position outside
//      [0, width) x [0, height) has no history. With a `reprojection` decision
//      (common/reproject.hpp), the history is tested for being the same surface:
//      none where the decision says disoccluded; the history filter where all taps
//      of its 2x2 footprint with positive bilinear weight are consistent; else the
//      decision's renormalised footprint (SVGF Sec. 4.1: 2x2 bilinear over the
//      consistent taps, or its 3x3 fallback), which leaves the other surfaces out.
//   2. rectification: a box in YCoCg around the 3x3 neighbourhood of the current
//      frame, either its min/max (Karis 2014) or mean +- gamma * stddev (variance
//      clipping, Salvi 2016, "An Excursion in Temporal Supersampling", GDC); the
//      history is clamped to the box per component, or clipped along the segment
//      from the box centre to the history ("neighbourhood clipping", Karis 2014;
//      a component within 2^-16 of the box's size of a face counts as inside, so
//      fp32 rounding cannot clip a history lying on a flat box's face).
//   3. output = lerp(history', current, alpha) (exponential moving average), negative
//      components (a YCoCg box corner need not be a valid RGB colour) set to 0.
// Without history (first frame, after resetHistory(), out-of-screen motion, a
// disocclusion) the output is the current colour. Output alpha is 1.
#include <cstdint>
#include <string>

#include <hush/passes/settings.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

enum class TaaBox : uint32_t {
    MinMax = 0,     // per-component min and max of the 3x3 neighbourhood (Karis 2014)
    Variance = 1,   // mean +- gamma * stddev of the 3x3 neighbourhood (Salvi 2016)
};

// How the history is resampled at the (sub-pixel) previous position.
enum class TaaHistoryFilter : uint32_t {
    Bilinear = 0,     // 2x2 taps, tent weights
    CatmullRom = 1,   // 4x4 taps, Catmull & Rom 1974 spline = Keys 1981 cubic, a = -0.5
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
    // Not Karis 2014's bilinear: resampling the history bilinearly every frame blurs
    // it (Yang et al. 2009, "Amortized Supersampling", analyse this reprojection
    // blur), and the blur lies inside the neighbourhood box, so rectification cannot
    // undo it. Catmull-Rom history is what Jimenez 2016 ("Filmic SMAA", SIGGRAPH
    // Advances course) uses against it; docs/passes/display.md has the measurements.
    TaaHistoryFilter historyFilter = TaaHistoryFilter::CatmullRom;
};

inline constexpr EnumNames<TaaBox, 2> kTaaBoxNames{{{"minmax", TaaBox::MinMax}, {"variance", TaaBox::Variance}}};
inline constexpr EnumNames<TaaRectify, 2> kTaaRectifyNames{{{"clamp", TaaRectify::Clamp}, {"clip", TaaRectify::Clip}}};
inline constexpr EnumNames<TaaHistoryFilter, 2> kTaaHistoryFilterNames{
    {{"bilinear", TaaHistoryFilter::Bilinear}, {"catmull-rom", TaaHistoryFilter::CatmullRom}}};

template <class V> void describe(V&& v, TaaSettings& s) {
    v.field("alpha", s.alpha, Range{0.0, 1.0});
    v.field("box", s.box, kTaaBoxNames);
    v.field("rectify", s.rectify, kTaaRectifyNames);
    v.field("varianceGamma", s.varianceGamma, Range{0.0, kUnbounded});
    v.field("historyFilter", s.historyFilter, kTaaHistoryFilterNames);
}

// Adds pass "<name>". `color`: rgba (rgb used); `motion`: rg, in pixels (any float
// formats, full output size); `reprojection`: optional, common/reproject's decision
// for the same motion. Returns the anti-aliased colour, rgba32f transient "<name>";
// its last-frame value (its graph history) is the TAA history.
//
// Give `reprojection` where there is one, above all when the frames are not
// jittered: their edges are point sampled, so when an edge crosses a pixel centre
// the pixel switches surface, yet the history at its previous position (a fraction
// of a pixel away) is still the old surface's colour; both colours lie in the 3x3
// neighbourhood, so rectification keeps it and the output lags behind the edge.
// On the tracer's cornell sequence that lag, not resampling blur, was most of the
// error TAA added (docs/passes/display.md).
graph::TextureHandle addTaaPass(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                graph::TextureHandle motion, const TaaSettings& settings = {},
                                graph::TextureHandle reprojection = {});

} // namespace hush::passes
