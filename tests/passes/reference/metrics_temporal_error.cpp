#include "reference/metrics_temporal_error.hpp"

#include <cmath>

#include "reference/metrics_error_metrics.hpp"

namespace hush::passes_test::reference {

TemporalErrorResult temporalError(const FloatImage& current, const FloatImage& previous) {
    const double weights[3] = {0.2126, 0.7152, 0.0722};   // Rec. 709 luminance
    TemporalErrorResult r;
    double sum = 0;
    for (uint32_t y = 0; y < current.height; ++y)
        for (uint32_t x = 0; x < current.width; ++x) {
            if (!finiteRgb(current, x, y) || !finiteRgb(previous, x, y)) {
                ++r.nonFinitePixels;
                continue;
            }
            ++r.pixels;
            for (uint32_t c = 0; c < 3; ++c)
                sum += weights[c] * std::fabs(double(current.at(x, y, c)) - double(previous.at(x, y, c)));
        }
    r.error = r.pixels ? sum / double(r.pixels) : 0.0;
    return r;
}

} // namespace hush::passes_test::reference
