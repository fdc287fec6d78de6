#include "reference/svgf_variance_prefilter.hpp"

#include <cstdint>

namespace hush::passes_test::reference {

namespace {

bool inside(const FloatImage& image, int64_t x, int64_t y) {
    return x >= 0 && y >= 0 && x < int64_t(image.width) && y < int64_t(image.height);
}

} // namespace

FloatImage svgfVariancePrefilter(const FloatImage& illumVariance) {
    FloatImage out(illumVariance.width, illumVariance.height, 1);
    const double gauss[3] = {0.25, 0.5, 0.25};
    for (int y = 0; y < int(out.height); ++y)
        for (int x = 0; x < int(out.width); ++x) {
            double sum = 0.0, weights = 0.0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    if (!inside(out, x + dx, y + dy)) continue;
                    const double g = gauss[dx + 1] * gauss[dy + 1];
                    sum += g * illumVariance.at(uint32_t(x + dx), uint32_t(y + dy), 3);
                    weights += g;
                }
            out.at(uint32_t(x), uint32_t(y)) = float(sum / weights);
        }
    return out;
}

} // namespace hush::passes_test::reference
