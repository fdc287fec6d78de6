#pragma once
// SVGF's variance prefilter (Schied et al. 2017, Sec. 4.4, "Luminance"): a 3x3
// Gaussian of the luminance variance, used only inside the luminance edge-stopping
// function w_l (Eq. 5) of the a-trous level that follows; it is not propagated.
//
// Input: rgba32f "illum_variance" (rgb illumination, a luminance variance).
// Output: r32f transient "<name>": sum g(q) var(q) / sum g(q) over the taps inside
// the image, g = (1/4, 1/2, 1/4) x (1/4, 1/2, 1/4). Renormalising over the in-image
// taps keeps a constant variance constant up to the image border (no clamp-to-edge
// weighting of the border pixels), and a 1x1 image returns its own variance.
#include <string>

#include <hush/passes/node_context.hpp>

namespace hush::passes {

graph::TextureHandle addSvgfVariancePrefilterPass(NodeContext& ctx, const std::string& name,
                                                  graph::TextureHandle illumVariance);

} // namespace hush::passes
