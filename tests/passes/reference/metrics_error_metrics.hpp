#pragma once
// CPU reference of passes/metrics/error_metrics (MSE, RMSE, relative MSE, PSNR), in
// double precision, written from the definitions (docs/passes/metrics.md)
// independently of the shaders. finiteRgb is the rule every metrics reference uses
// to leave a pixel out.
#include <cstddef>
#include <cstdint>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// Images: at least 3 channels; RGB compared, the rest ignored. A pixel with a
// non-finite RGB component in either image is left out and counted.
struct ErrorMetricsResult {
    double mse = 0, rmse = 0, relMse = 0, psnr = 0;
    size_t pixels = 0, nonFinitePixels = 0;
};
ErrorMetricsResult errorMetrics(const FloatImage& image, const FloatImage& reference, double epsilon, double peak);

// Whether the RGB components of (x, y) are all finite.
bool finiteRgb(const FloatImage& image, uint32_t x, uint32_t y);

} // namespace hush::passes_test::reference
