#pragma once
// SVGF variance estimation (Schied et al. 2017, Sec. 4.2): the luminance variance
// that steers the a-trous filter's luminance edge-stopping function.
//
// Where the history holds at least minHistoryLength frames:
//   variance = max(0, mu2 - mu1^2)   (the integrated moments of the temporal pass)
//   colour   = the integrated colour
// Where it is shorter (after a disocclusion), a 7x7 bilateral estimate over the
// neighbours q of p, with the a-trous filter's geometric weights (Sec. 4.4):
//   w(p, q) = exp(-|z(p) - z(q)| / (sigma_z |grad z(p) . (p - q)| + depthEpsilon))
//           * max(0, n(p) . n(q))^sigma_n                       (w(p, p) = 1)
//   mu_s    = sum w mu(q) / sum w,   colour = sum w C(q) / sum w,
//   variance = max(0, mu2_s - mu1_s^2) * (shortHistoryBoost ? minHistoryLength / n : 1)
// No luminance weight (the luminance is what is being estimated). The boost is not
// in the paper: it is the practice of SVGF implementations, which trust the few-
// sample spatial estimate less, so the first frames after a disocclusion are
// filtered harder; it fades as n reaches minHistoryLength.
#include <string>

#include <hush/passes/settings.hpp>
#include <hush/passes/common/surface.hpp>
#include <hush/passes/node_context.hpp>
#include <hush/passes/svgf/temporal_accumulation.hpp>

namespace hush::passes {

struct SvgfVarianceSettings {
    // Sec. 4.2: "Where our temporal history is limited (<4 frames after a
    // disocclusion), we instead estimate the variance spatially, using a 7x7
    // bilateral filter with weights driven by depths and world-space normals."
    float minHistoryLength = 4.0f;
    int radius = 3;   // 7x7
    // Sec. 4.4: sigma_z = 1, sigma_n = 128 (shared with the a-trous weights).
    float sigmaZ = 1.0f;
    float sigmaN = 128.0f;
    // Eq. 3's epsilon, in depth units: keeps w_z defined on fronto-parallel surfaces
    // (zero gradient), where any depth difference then rejects the neighbour.
    float depthEpsilon = 1e-4f;
    // Multiply the spatial estimate by minHistoryLength / n (see above).
    bool shortHistoryBoost = true;
};

template <class V> void describe(V&& v, SvgfVarianceSettings& s) {
    v.field("minHistoryLength", s.minHistoryLength, Range{0.0, 65536.0});
    v.field("radius", s.radius, Range{0, 16});
    v.field("sigmaZ", s.sigmaZ, Range{0.0, kUnbounded});
    v.field("sigmaN", s.sigmaN, Range{0.0, kUnbounded});
    v.field("depthEpsilon", s.depthEpsilon, Range{0.0, kUnbounded});
    v.field("shortHistoryBoost", s.shortHistoryBoost);
}

// Adds pass "<name>"; returns rgba32f (transient "<name>"): rgb illumination, a variance.
graph::TextureHandle addSvgfVariancePass(NodeContext& ctx, const std::string& name, const SvgfTemporal& temporal,
                                         const Surface& surface, const SvgfVarianceSettings& settings = {});

} // namespace hush::passes
