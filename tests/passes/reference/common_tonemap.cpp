#include "reference/common_tonemap.hpp"

#include <algorithm>

namespace hush::passes_test::reference {

namespace {

double aces(double x) {
    // Narkowicz 2016: x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), saturated.
    x = std::max(x, 0.0);
    if (x > 1e100) return 1.0;   // the curve's limit is 2.51 / 2.43 > 1: saturated
    const double y = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
    return std::clamp(y, 0.0, 1.0);
}

double reinhard(double x) {
    x = std::max(x, 0.0);
    return x / (1.0 + x);
}

} // namespace

void tonemapColor(const passes::TonemapSettings& settings, const double in[3], double out[3]) {
    double x[3];
    for (int c = 0; c < 3; ++c) x[c] = std::max(in[c] * double(settings.exposure), 0.0);
    switch (settings.op) {
    case passes::TonemapOperator::AcesFit:
        for (int c = 0; c < 3; ++c) out[c] = aces(x[c]);
        return;
    case passes::TonemapOperator::ReinhardPerChannel:
        for (int c = 0; c < 3; ++c) out[c] = reinhard(x[c]);
        return;
    case passes::TonemapOperator::ReinhardLuminance: {
        // rgb * L_d / L with L_d = L / (1 + L); L = 0 -> black.
        const double lum = 0.2126 * x[0] + 0.7152 * x[1] + 0.0722 * x[2];
        for (int c = 0; c < 3; ++c) out[c] = lum > 0.0 ? std::min(x[c] * reinhard(lum) / lum, 1.0) : 0.0;
        return;
    }
    }
}

FloatImage tonemap(const FloatImage& radiance, const passes::TonemapSettings& settings) {
    FloatImage out(radiance.width, radiance.height, 4, 1.0f);
    for (uint32_t y = 0; y < out.height; ++y)
        for (uint32_t x = 0; x < out.width; ++x) {
            const double in[3] = {radiance.at(x, y, 0), radiance.at(x, y, 1), radiance.at(x, y, 2)};
            double mapped[3];
            tonemapColor(settings, in, mapped);
            for (uint32_t c = 0; c < 3; ++c) out.at(x, y, c) = float(mapped[c]);
        }
    return out;
}

} // namespace hush::passes_test::reference
