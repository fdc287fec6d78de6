#pragma once
// Mara et al. 2017's temporal stages (seed 000 Sec. 3.4, Eq. 11, Fig. 2 stages 3 and
// 8; docs/passes/mara.md). Each blends the current 1-path estimate x with last
// frame's history, clamped to the 3x3 neighbourhood of x, by h * c, where
//   c = h * (1 - smoothstep(d0, d1, |X_expected - X_actual|))   (metres)
// is how far last frame's world position at the reprojected pixel (X_actual) is from
// this pixel's (X_expected). Output rgba32f: rgb the blend, alpha c (the disocclusion
// stage reads it). c = 0 (no history) on the first frame, after resetHistory(), and
// where the reprojected pixel leaves the image.
//
// Not the shared reprojection decision (common/reproject.hpp): the paper's test is a
// world-space distance with thresholds in metres, and the glossy stage reprojects
// the virtual position, which no depth-slope test over screen neighbours can judge.
#include <string>

#include <hush/passes/frame_camera.hpp>
#include <hush/passes/node_context.hpp>
#include <hush/passes/settings.hpp>

namespace hush::passes {

struct MaraTemporalSettings {
    // Sec. 3.4: "we empirically chose h = 0.98, d0 = 0.05 m, d1 = 0.07 m".
    float hysteresis = 0.98f;
    float d0 = 0.05f;   // metres: full confidence below
    float d1 = 0.07f;   // metres: none above
};

template <class V> void describe(V&& v, MaraTemporalSettings& s) {
    v.field("hysteresis", s.hysteresis, Range{0.0, 1.0});
    v.field("d0", s.d0, Range{0.0, 1e6});
    v.field("d1", s.d1, Range{0.0, 1e6});
}

// Stage 3: last frame's sample at p + 0.5 + motion. `history` is last frame's value
// of what the chain feeds back (the pre-bilateral output); `positionHistory` last
// frame's `position`. The camera supplies metresPerUnit each frame.
graph::TextureHandle addMaraMatteTemporalPass(NodeContext& ctx, const std::string& name, graph::TextureHandle matte,
                                              graph::TextureHandle motion, graph::TextureHandle position,
                                              graph::TextureHandle history, graph::TextureHandle positionHistory,
                                              FrameCameraRef camera, const MaraTemporalSettings& settings = {});

// Stage 8: last frame's sample where last frame's camera saw the virtual position.
// Its own output is its history; `virtualposHistory` is last frame's `virtualpos`.
graph::TextureHandle addMaraGlossyTemporalPass(NodeContext& ctx, const std::string& name, graph::TextureHandle glossy,
                                               graph::TextureHandle virtualpos, graph::TextureHandle virtualposHistory,
                                               FrameCameraRef camera, const MaraTemporalSettings& settings = {});

} // namespace hush::passes
