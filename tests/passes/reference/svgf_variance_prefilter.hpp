#pragma once
// CPU reference of SVGF's variance prefilter (Schied et al. 2017, Sec. 4.4), in
// double precision, written from the paper and the renormalisation stated in
// passes/include/hush/passes/svgf/variance_prefilter.hpp, independently of the shader.
#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// 1 channel: the 3x3 Gaussian (1/4, 1/2, 1/4)^2 of illumVariance's alpha,
// renormalised over the in-image taps.
FloatImage svgfVariancePrefilter(const FloatImage& illumVariance);

} // namespace hush::passes_test::reference
