#include "reference/metrics_error_metrics.hpp"

#include <cmath>
#include <limits>

namespace hush::passes_test::reference {

bool finiteRgb(const FloatImage& image, uint32_t x, uint32_t y) {
    for (uint32_t c = 0; c < 3; ++c)
        if (!std::isfinite(image.at(x, y, c))) return false;
    return true;
}

ErrorMetricsResult errorMetrics(const FloatImage& image, const FloatImage& reference, double epsilon, double peak) {
    ErrorMetricsResult r;
    double squared = 0, relative = 0;
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x) {
            if (!finiteRgb(image, x, y) || !finiteRgb(reference, x, y)) {
                ++r.nonFinitePixels;
                continue;
            }
            ++r.pixels;
            for (uint32_t c = 0; c < 3; ++c) {
                const double a = image.at(x, y, c), b = reference.at(x, y, c);
                squared += (a - b) * (a - b);
                relative += (a - b) * (a - b) / (b * b + epsilon);
            }
        }
    const double n = 3.0 * double(r.pixels);
    r.mse = squared / n;
    r.rmse = std::sqrt(r.mse);
    r.relMse = relative / n;
    r.psnr = r.mse == 0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(peak * peak / r.mse);
    return r;
}

} // namespace hush::passes_test::reference
