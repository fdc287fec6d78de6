#pragma once
// CPU reference of SVGF's a-trous filter (Schied et al. 2017, Sec. 4.3-4.4), in
// double precision, written from the paper's equations and the guards stated in
// passes/include/hush/passes/svgf/atrous.hpp, independently of the shaders.
// svgfAtrousLevels runs the variance prefilter's reference
// (reference/svgf_variance_prefilter.hpp) before every level.
#include <vector>

#include <hush/passes/svgf/atrous.hpp>

#include "pass_test_util.hpp"
#include "reference/common_surface.hpp"
#include "reference/svgf_variance_prefilter.hpp"

namespace hush::passes_test::reference {

// 4 channels: one a-trous level (Eq. 1-5, variance propagation of Sec. 4.3).
// `surface` holds normalDepth and gradientMesh as the Surface node packs them.
FloatImage svgfAtrousLevel(const FloatImage& illumVariance, const FloatImage& prefilteredVariance,
                           const SurfaceImages& surface, uint32_t level, const passes::SvgfAtrousSettings& s = {});

// Every level's output, level i filtering level i-1's with its own prefilter.
std::vector<FloatImage> svgfAtrousLevels(const FloatImage& illumVariance, const SurfaceImages& surface,
                                         const passes::SvgfAtrousSettings& s = {});

} // namespace hush::passes_test::reference
