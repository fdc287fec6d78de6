#include "rdae_output.hpp"

#include <algorithm>
#include <cmath>

namespace hush::passes_test::reference {

FloatImage rdaeOutput(const Tensor& t, uint32_t width, uint32_t height) {
    FloatImage out(width, height, 4, 1.0f);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x)
            for (uint32_t c = 0; c < 3; ++c) {
                const double v = std::isnan(t.at(c, x, y)) ? 0.0 : std::clamp(double(t.at(c, x, y)), 0.0, 9.2);
                out.at(x, y, c) = float(std::min(std::pow(v, 5.0), 65504.0));
            }
    return out;
}

} // namespace hush::passes_test::reference
