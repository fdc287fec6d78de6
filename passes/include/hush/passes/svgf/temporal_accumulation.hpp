#pragma once
// SVGF temporal accumulation (Schied et al. 2017, Sec. 4.1 and the moments of 4.2):
// the demodulated 1-spp illumination is blended with last frame's colour history,
// read through a reprojection decision (common/reproject.hpp), by an exponential
// moving average; so are the first and second raw moments of its luminance, which
// the variance estimate (svgf/variance_estimate.hpp) turns into a variance.
//
//   n   = disoccluded ? 1 : min(n_prev + 1, maxHistoryLength)
//   a   = disoccluded ? 1 : max(alpha, 1 / n)          (cumulative average first)
//   C'  = a * C + (1 - a) * C'_prev
//   mu' = a_m * (l, l^2) + (1 - a_m) * mu'_prev,  a_m = max(momentsAlpha, 1 / n)
//   l   = Rec. 709 luminance of C (0.2126, 0.7152, 0.0722)
// where C'_prev, mu'_prev and n_prev are the histories fetched through the
// decision (renormalised bilinear or 3x3 weights). A disocclusion, the first frame
// and a history reset (PassContext::historyValid() false) give C' = C, n = 1.
#include <string>

#include <hush/passes/settings.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

struct SvgfTemporalSettings {
    // Sec. 4.1: "We found alpha = 0.2 worked best."
    float alpha = 0.2f;
    // Sec. 4.2 reuses the accumulation for the moments; ALGORITHMS.md: 0.2 as well.
    float momentsAlpha = 0.2f;
    // Cap of the history length counter. The paper gives none; with alpha = 0.2 the
    // blend is the same for every n >= 5, so the cap only bounds the counter (32, as
    // in common SVGF implementations, and what later passes read as "long").
    float maxHistoryLength = 32.0f;
};

template <class V> void describe(V&& v, SvgfTemporalSettings& s) {
    v.field("alpha", s.alpha, Range{0.0, 1.0});
    v.field("momentsAlpha", s.momentsAlpha, Range{0.0, 1.0});
    v.field("maxHistoryLength", s.maxHistoryLength, Range{1.0, 65536.0});
}

struct SvgfTemporal {
    // rgba32f, transient "<name>": integrated illumination in rgb, alpha 1.
    graph::TextureHandle color;
    // rgba32f, transient "<name>.moments": (mu1, mu2, history length n, 0).
    graph::TextureHandle moments;
};

// Adds pass "<name>". `reprojection` is addReprojectPass's decision. `colorHistory`
// is last frame's colour: in the SVGF chain a history bound to the first a-trous
// level's output (Sec. 4.3, "we output the filtered color from the first wavelet
// iteration as our color history"; RenderGraph::bindHistory); left invalid, the
// history of this pass's own output. The moments history is always its own.
SvgfTemporal addSvgfTemporalPass(NodeContext& ctx, const std::string& name, graph::TextureHandle illumination,
                                 graph::TextureHandle reprojection, graph::TextureHandle colorHistory = {},
                                 const SvgfTemporalSettings& settings = {});

} // namespace hush::passes
