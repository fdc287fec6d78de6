#pragma once
// The edge-avoiding a-trous wavelet filter of Dammertz, Sewtz, Hanika and Lensch
// 2010, "Edge-Avoiding A-Trous Wavelet Transform for fast Global Illumination
// Filtering" (HPG 2010): the baseline SVGF compares against (SVGF Sec. 5.1, "EAW";
// "EAW_orig" without temporal accumulation, which is this node's filter alone).
// One level gathers a 5x5 footprint with step 2^level:
//   c'(p) = sum h(q) w(p,q) c(q) / sum h(q) w(p,q)
// h = (1/16, 1/4, 3/8, 1/4, 1/16) per axis (B3 spline), w = w_rt w_n w_x with
//   w_i = exp(-||I_i(p) - I_i(q)||^2 / sigma_i^2)
// on the colour (rt), the normal (n) and the world position (x). The colour sigma
// halves at every level, sigma_rt^i = 2^-i sigma_rt; the others are fixed. The
// parameters are global: no variance guidance, no temporal reuse.
//
// Guards: each sigma^2 is at least 1e-30 (a zero sigma makes an exact match
// weigh 1 and anything else 0, never 0/0); the centre tap weighs 1, so the weight
// sum is at least (3/8)^2; taps outside the image are skipped. hush addition:
// pixels with a zero normal (no surface) are copied unchanged and surface pixels
// skip them, as in SVGF's a-trous node (docs/passes/eaw.md).
//
// Colour: rgba32f, rgb filtered (demodulated illumination), alpha copied from the
// centre. Normal: xyz (unit, or 0 where no surface). Position: world xyz.
#include <cstdint>
#include <string>

#include <hush/passes/settings.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

// The paper tunes its sigmas by hand per scene (they are inputs of its filter, not
// constants); these defaults suit demodulated illumination of order 1 in a scene
// modelled in metres. Multiply sigmaX by the scene's units per metre (1000 for the
// millimetre Cornell box) and sigmaRt by the illumination's scale.
struct EawSettings {
    uint32_t iterations = 5;   // five levels, as SVGF's (and Dammertz's figures)
    float sigmaRt = 1.0f;      // colour, illumination units, at level 0 (halved per level)
    float sigmaN = 0.3f;       // ||n(p) - n(q)||: a 30 degree crease (0.52) weighs exp(-3)
    float sigmaX = 0.5f;       // world units: a 1 m depth step weighs exp(-4)
    // With a depth input, positions are compared relative to the centre's depth,
    // ||x_p - x_q|| / z_p, with this sigma instead of sigmaX: scale-free, so one value
    // suits every scene. 0.1: neighbours 16 pixels apart on one surface (about 0.05 z
    // at a 40 degree field of view and 256 pixels) weigh 0.8; a step of z/4 weighs exp(-6).
    float sigmaXRelative = 0.1f;
    // Non-zero: the colour weight is scale-free, exp(-||c_p - c_q||^2 / (s L_p)^2) with
    // s = 2^-level sigmaRtRelative and L_p the kernel-weighted mean luminance of the
    // level's surface taps (at least 1e-20), instead of the absolute sigmaRt. The
    // default, so that the filter does the same on radiance of any scale (exposure,
    // units of another renderer); 0 restores the paper's absolute sigma.
    float sigmaRtRelative = 7.0f;
};

template <class V> void describe(V&& v, EawSettings& s) {
    v.field("iterations", s.iterations, Range{0, 16});
    v.field("sigmaRt", s.sigmaRt, Range{0.0, kUnbounded});
    v.field("sigmaN", s.sigmaN, Range{0.0, kUnbounded});
    v.field("sigmaX", s.sigmaX, Range{0.0, kUnbounded});
    v.field("sigmaXRelative", s.sigmaXRelative, Range{0.0, kUnbounded});
    v.field("sigmaRtRelative", s.sigmaRtRelative, Range{0.0, kUnbounded});
}

// The a-trous step of `level`: 2^level, capped at 2^16 (every tap but the centre
// then lies outside any texture the RHI can make).
uint32_t eawAtrousStep(uint32_t level);
// sigma_rt at `level`: 2^-level sigma_rt (Dammertz et al. 2010), or 2^-level
// sigmaRtRelative when that is non-zero (then relative to the local luminance).
float eawColorSigma(const EawSettings& s, uint32_t level);

// Adds pass "<name>": one level. Returns the rgba32f transient "<name>".
graph::TextureHandle addEawAtrousPass(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                      graph::TextureHandle normal, graph::TextureHandle position, uint32_t level,
                                      const EawSettings& s = {});

// Adds "<name>.level.<i>" for i in 0..iterations-1, each filtering the previous
// one's output; returns the last (color itself when iterations = 0).
graph::TextureHandle addEawAtrousLevels(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                        graph::TextureHandle normal, graph::TextureHandle position,
                                        const EawSettings& s = {});

// The same with a linear depth input: the position weight becomes scale-free,
// exp(-||x_p - x_q||^2 / (sigmaXRelative z_p)^2), z_p at least 1e-20.
graph::TextureHandle addEawAtrousPass(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                      graph::TextureHandle normal, graph::TextureHandle position,
                                      graph::TextureHandle depth, uint32_t level, const EawSettings& s = {});
graph::TextureHandle addEawAtrousLevels(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                        graph::TextureHandle normal, graph::TextureHandle position,
                                        graph::TextureHandle depth, const EawSettings& s = {});

} // namespace hush::passes
