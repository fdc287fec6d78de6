#include "reference/common_remodulate.hpp"

#include "reference/common_demodulate.hpp"

namespace hush::passes_test::reference {

FloatImage remodulate(const FloatImage& a, const FloatImage* b, const FloatImage& albedo, float eps) {
    FloatImage out(a.width, a.height, 4, 1.0f);
    for (uint32_t y = 0; y < out.height; ++y)
        for (uint32_t x = 0; x < out.width; ++x) {
            float f[3];
            factor(albedo, x, y, eps, f);
            for (uint32_t c = 0; c < 3; ++c)
                out.at(x, y, c) = (a.at(x, y, c) + (b ? b->at(x, y, c) : 0.0f)) * f[c];
        }
    return out;
}

} // namespace hush::passes_test::reference
