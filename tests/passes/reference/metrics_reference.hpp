#pragma once
// CPU references of passes/metrics, in double precision, written from the
// definitions (docs/passes/metrics.md) independently of the shaders: SSIM follows
// the form of Wang's ssim_index.m (sigma^2 = E[x^2] - mu^2 over a 2D window), where
// the shader uses two passes over separable weights.
#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// Images: at least 3 channels; RGB compared, the rest ignored. A pixel with a
// non-finite RGB component in either image is left out and counted.
struct ErrorMetricsResult {
    double mse = 0, rmse = 0, relMse = 0, psnr = 0;
    size_t pixels = 0, nonFinitePixels = 0;
};
ErrorMetricsResult errorMetrics(const FloatImage& image, const FloatImage& reference, double epsilon, double peak);

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

// Mean over pixels of the Rec. 709 luminance of |current - previous|.
struct TemporalErrorResult {
    double error = 0;
    size_t pixels = 0, nonFinitePixels = 0;
};
TemporalErrorResult temporalError(const FloatImage& current, const FloatImage& previous);

} // namespace hush::passes_test::reference
