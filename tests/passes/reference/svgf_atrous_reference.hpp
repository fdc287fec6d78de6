#pragma once
// CPU references of SVGF's a-trous filter and its variance prefilter (Schied et al.
// 2017, Sec. 4.3-4.4), in double precision, written from the paper's equations and
// the guards stated in passes/include/hush/passes/svgf/atrous.hpp, independently of
// the shaders.
#include <vector>

#include <hush/passes/svgf/atrous.hpp>

#include "pass_test_util.hpp"
#include "reference/common_reference.hpp"

namespace hush::passes_test::reference {

// 1 channel: the 3x3 Gaussian (1/4, 1/2, 1/4)^2 of illumVariance's alpha,
// renormalised over the in-image taps.
FloatImage svgfVariancePrefilter(const FloatImage& illumVariance);

// 4 channels: one a-trous level (Eq. 1-5, variance propagation of Sec. 4.3).
// `surface` holds normalDepth and gradientMesh as the Surface node packs them.
FloatImage svgfAtrousLevel(const FloatImage& illumVariance, const FloatImage& prefilteredVariance,
                           const SurfaceImages& surface, uint32_t level, const passes::SvgfAtrousSettings& s = {});

// Every level's output, level i filtering level i-1's with its own prefilter.
std::vector<FloatImage> svgfAtrousLevels(const FloatImage& illumVariance, const SurfaceImages& surface,
                                         const passes::SvgfAtrousSettings& s = {});

} // namespace hush::passes_test::reference
