#pragma once
// Mara et al. 2017 stages 9 and 10, the glossy blur (seed 000 Sec. 3.4): a separable
// cross-bilateral Gaussian, "<name>.horizontal" then "<name>.vertical", whose standard
// deviation in pixels follows the centre's roughness (GGX alpha),
//   sigma = sigmaScale * roughness^roughnessExponent + sigmaEpsilon,
// over |offset| <= ceil(3 sigma) (at most 32), with the plane and normal weights of
// the sparse bilateral (mara/sparse_bilateral.hpp). Separable because a sparse pattern
// leaves dithering in glossy reflections when reprojection fails (Sec. 3.4).
#include <string>

#include <hush/passes/common/surface.hpp>
#include <hush/passes/node_context.hpp>
#include <hush/passes/settings.hpp>

namespace hush::passes {

struct MaraGlossyBilateralSettings {
    float sigmaScale = 7.0f;            // Sec. 3.4: sigma = 7 roughness^0.1 + epsilon
    float roughnessExponent = 0.1f;
    float sigmaEpsilon = 1e-3f;         // the paper's epsilon: a mirror keeps a (vanishing) kernel
    float planeSigma = 0.02f;           // as MaraSparseBilateralSettings
    float normalPower = 32.0f;
};

template <class V> void describe(V&& v, MaraGlossyBilateralSettings& s) {
    v.field("sigmaScale", s.sigmaScale, Range{0.0, 10.0});
    v.field("roughnessExponent", s.roughnessExponent, Range{0.0, 10.0});
    v.field("sigmaEpsilon", s.sigmaEpsilon, Range{1e-6, 10.0});
    v.field("planeSigma", s.planeSigma, Range{1e-6, kUnbounded});
    v.field("normalPower", s.normalPower, Range{0.0, 1024.0});
}

// Returns the blurred rgb (alpha copied), rgba32f "<name>.vertical".
graph::TextureHandle addMaraGlossyBilateralPasses(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                                  graph::TextureHandle roughness, const Surface& surface,
                                                  graph::TextureHandle position,
                                                  const MaraGlossyBilateralSettings& settings = {});

} // namespace hush::passes
