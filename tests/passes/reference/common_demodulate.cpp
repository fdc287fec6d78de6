#include "reference/common_demodulate.hpp"

#include <algorithm>

namespace hush::passes_test::reference {

void factor(const FloatImage& albedo, uint32_t x, uint32_t y, float eps, float out[3]) {
    bool allBelow = true;
    for (uint32_t c = 0; c < 3; ++c) allBelow = allBelow && albedo.at(x, y, c) < eps;
    for (uint32_t c = 0; c < 3; ++c) out[c] = allBelow ? 1.0f : std::max(albedo.at(x, y, c), eps);
}

FloatImage demodulate(const FloatImage& radiance, const FloatImage& albedo, float eps) {
    FloatImage out(radiance.width, radiance.height, 4, 1.0f);
    for (uint32_t y = 0; y < out.height; ++y)
        for (uint32_t x = 0; x < out.width; ++x) {
            float f[3];
            factor(albedo, x, y, eps, f);
            for (uint32_t c = 0; c < 3; ++c) out.at(x, y, c) = radiance.at(x, y, c) / f[c];
        }
    return out;
}

} // namespace hush::passes_test::reference
