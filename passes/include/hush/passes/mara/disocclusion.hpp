#pragma once
// Mara et al. 2017 stage 5, disocclusion detection (seed 000 Sec. 3.4): the radius of
// the final matte bilateral, large where temporal confidence was low nearby,
//   r = (1 - min over a (2R+1) x (2R+1) box of c) * R,   R = maxRadius * image width,
// times lowConfidenceScale where the pixel's own c < lowConfidence; the box minimum
// is two 1D min passes, "<name>.horizontal" and "<name>.vertical".
#include <string>

#include <hush/passes/node_context.hpp>
#include <hush/passes/settings.hpp>

namespace hush::passes {

struct MaraDisocclusionSettings {
    float maxRadius = 0.05f;          // of the image width: "R = screen width / 20"
    float lowConfidence = 0.5f;       // "a multiplier of six where c < 1/2"
    float lowConfidenceScale = 6.0f;
};

template <class V> void describe(V&& v, MaraDisocclusionSettings& s) {
    v.field("maxRadius", s.maxRadius, Range{0.0, 1.0});
    v.field("lowConfidence", s.lowConfidence, Range{0.0, 1.0});
    v.field("lowConfidenceScale", s.lowConfidenceScale, Range{0.0, 1000.0});
}

// R in pixels for an image `width` pixels wide: round(maxRadius * width).
int maraDisocclusionBoxRadius(const MaraDisocclusionSettings& settings, uint32_t width);

// `temporal`: the matte temporal output, c in alpha. Returns the radius map, r32f
// "<name>", in pixels.
graph::TextureHandle addMaraDisocclusionPass(NodeContext& ctx, const std::string& name, graph::TextureHandle temporal,
                                             const MaraDisocclusionSettings& settings = {});

} // namespace hush::passes
