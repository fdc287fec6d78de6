#pragma once
// CPU reference of Mara et al. 2017 stages 9 and 10 (seed 000 Sec. 3.4): the separable
// cross-bilateral Gaussian with sigma = scale * roughness^exponent + epsilon.
#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

struct MaraGlossyBilateralParams {
    double sigmaScale = 7.0, roughnessExponent = 0.1, sigmaEpsilon = 1e-3, planeSigma = 0.02, normalPower = 32.0;
};

// One direction (vertical: along y).
FloatImage maraGlossyBilateral(const FloatImage& color, const FloatImage& roughness, const FloatImage& normalDepth,
                               const FloatImage& position, bool vertical, const MaraGlossyBilateralParams& params);

} // namespace hush::passes_test::reference
