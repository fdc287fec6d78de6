#pragma once
// CPU reference of passes/common/tonemap, written from the formulas in its header
// (Narkowicz 2016; Reinhard et al. 2002, Eq. 3) in double precision, independently of
// the shader and of the public CPU tonemap functions.
#include <hush/passes/common/tonemap.hpp>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// One linear HDR colour through the tonemap settings' operator.
void tonemapColor(const passes::TonemapSettings& settings, const double in[3], double out[3]);
// rgb tonemapped, alpha 1 (4 channels).
FloatImage tonemap(const FloatImage& radiance, const passes::TonemapSettings& settings);

} // namespace hush::passes_test::reference
