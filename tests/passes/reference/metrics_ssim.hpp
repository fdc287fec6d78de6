#pragma once
// CPU reference of passes/metrics/ssim, in double precision, written from the
// definition (Wang et al. 2004; docs/passes/metrics.md) independently of the shaders:
// it follows the form of Wang's ssim_index.m (sigma^2 = E[x^2] - mu^2 over a 2D
// window), where the shader uses two passes over separable weights.
#include <cstddef>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// Mean SSIM: 11 x 11 Gaussian (sigma), valid window positions along axes of >= 11
// pixels, every pixel with the window clipped and renormalised along shorter axes;
// windows with a non-finite RGB value left out and counted. `map` is the shader's
// layout: (SSIM, 1, 0, 0) counted, (0, 0, 1, 0) excluded, 0 elsewhere.
struct SsimResult {
    double ssim = 0;
    size_t windows = 0, excludedWindows = 0;
    FloatImage map;
};
SsimResult ssim(const FloatImage& image, const FloatImage& reference, double k1, double k2, double dynamicRange,
                double sigma);

} // namespace hush::passes_test::reference
