#include "rdae_input.hpp"

#include <algorithm>
#include <cmath>

namespace hush::passes_test::reference {

Tensor rdaeInput(const FloatImage& illumination, const FloatImage& normal, const FloatImage& depth,
                 const FloatImage& roughness, const std::array<float, 16>& view, float metresPerUnit, uint32_t levels) {
    const uint32_t m = 1u << levels;
    const uint32_t w = (illumination.width + m - 1) / m * m, h = (illumination.height + m - 1) / m * m;
    Tensor t(7, w, h);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const uint32_t sx = std::min(x, illumination.width - 1), sy = std::min(y, illumination.height - 1);
            for (uint32_t c = 0; c < 3; ++c)
                t.at(c, x, y) = float(std::pow(std::max(double(illumination.at(sx, sy, c)), 0.0), 0.2));
            // Column-major view: view-space component r = sum_k view[4k + r] n_k.
            for (uint32_t r = 0; r < 2; ++r) {
                double v = 0.0;
                for (uint32_t k = 0; k < 3; ++k) v += double(view[4 * k + r]) * normal.at(sx, sy, k);
                t.at(3 + r, x, y) = float(v);
            }
            const double d = std::max(double(depth.at(sx, sy, 0)) * metresPerUnit, 0.0);
            t.at(5, x, y) = float(d / (1.0 + d));
            t.at(6, x, y) = std::clamp(roughness.at(sx, sy, 0), 0.0f, 1.0f);
        }
    return t;
}

} // namespace hush::passes_test::reference
