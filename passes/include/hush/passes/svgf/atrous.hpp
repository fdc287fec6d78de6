#pragma once
// SVGF's variance-guided edge-avoiding a-trous wavelet filter (Schied et al. 2017,
// Sec. 4.3-4.4). One level gathers a 5x5 footprint with step 2^level:
//   c'(p)   = sum h(q) w(p,q) c(q) / sum h(q) w(p,q)                        (Eq. 1)
//   Var'(p) = sum h(q)^2 w(p,q)^2 Var(q) / (sum h(q) w(p,q))^2             (Sec. 4.3)
// h = (1/16, 1/4, 3/8, 1/4, 1/16) per axis, w = w_z w_n w_l (Eq. 2):
//   w_z = exp(-|z(p) - z(q)| / (sigma_z |grad z(p) . (p - q)| + eps_z))    (Eq. 3)
//   w_n = max(0, n(p) . n(q))^sigma_n                                       (Eq. 4)
//   w_l = exp(-|l(p) - l(q)| / (sigma_l sqrt(g3x3(Var(p))) + eps_l))       (Eq. 5)
// l = Rec. 709 luminance of the level's input, p - q in pixels (step included).
// The centre tap has w = 1, so the weight sum is at least (3/8)^2 and never 0.
// Taps outside the image are skipped (not clamped). Input variances below 0 count
// as 0.
//
// Pixels without a surface (mesh id < 0 or a zero normal) are copied unchanged
// (colour and variance), and a surface pixel skips the taps that have no surface:
// the background neither blurs nor bleeds into the geometry. See
// docs/passes/svgf-atrous.md for where this differs from the paper.
#include <cstdint>
#include <string>

#include <hush/passes/settings.hpp>
#include <hush/passes/common/surface.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

struct SvgfAtrousSettings {
    uint32_t iterations = 5;   // Sec. 4.3: a five-level transform (65x65 footprint)
    float sigmaZ = 1.0f;       // Sec. 4.4, Eq. 3
    float sigmaN = 128.0f;     // Sec. 4.4, Eq. 4
    float sigmaL = 4.0f;       // Sec. 4.4, Eq. 5
    // Eq. 3's eps, relative to the centre's depth: eps_z = depthEpsilon * |z(p)|
    // (at least 1e-20), so that one constant serves millimetre and metre scenes.
    // On a plane facing the camera (grad z = 0) a depth step of 0.1 % of the depth
    // weighs exp(-1).
    float depthEpsilon = 1e-3f;
    // Eq. 5's eps, in illumination units: where the variance is 0 only luminances
    // equal to within ~1e-10 blend (a noise-free region stays as it is).
    float luminanceEpsilon = 1e-10f;
};

template <class V> void describe(V&& v, SvgfAtrousSettings& s) {
    v.field("iterations", s.iterations, Range{0, 16});
    v.field("sigmaZ", s.sigmaZ, Range{0.0, kUnbounded});
    v.field("sigmaN", s.sigmaN, Range{0.0, kUnbounded});
    v.field("sigmaL", s.sigmaL, Range{0.0, kUnbounded});
    v.field("depthEpsilon", s.depthEpsilon, Range{0.0, kUnbounded});
    v.field("luminanceEpsilon", s.luminanceEpsilon, Range{1e-30, kUnbounded});  // > 0: Eq. 5 divides by it where the variance is 0
}

// The a-trous step of `level`: 2^level, capped at 2^16 (a step that large puts
// every tap but the centre outside any texture the RHI can make).
uint32_t svgfAtrousStep(uint32_t level);

// Adds pass "<name>": one a-trous level. illumVariance: rgba32f (rgb illumination,
// a luminance variance); prefilteredVariance: r32f from addSvgfVariancePrefilterPass
// of the same illumVariance. Returns the rgba32f transient "<name>" (rgb filtered
// illumination, a propagated variance).
graph::TextureHandle addSvgfAtrousPass(NodeContext& ctx, const std::string& name, graph::TextureHandle illumVariance,
                                       graph::TextureHandle prefilteredVariance, const Surface& surface,
                                       uint32_t level, const SvgfAtrousSettings& s = {});

struct SvgfAtrousResult {
    graph::TextureHandle filtered;     // the last level's output
    graph::TextureHandle firstLevel;   // level 0's output: the colour history (Sec. 4.3)
};

// Adds, for i in 0..iterations-1, "<name>.prefilter.<i>" and "<name>.level.<i>",
// level i filtering level i-1's output with step 2^i. Level outputs are transients
// "<name>.level.<i>"; firstLevel is what SvgfChain binds its colour history to.
// With iterations = 0 both handles are illumVariance itself.
SvgfAtrousResult addSvgfAtrousLevels(NodeContext& ctx, const std::string& name, graph::TextureHandle illumVariance,
                                     const Surface& surface, const SvgfAtrousSettings& s = {});

} // namespace hush::passes
