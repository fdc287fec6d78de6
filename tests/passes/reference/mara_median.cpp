#include "reference/mara_median.hpp"

#include <algorithm>
#include <array>

namespace hush::passes_test::reference {

FloatImage maraMedian(const FloatImage& color) {
    FloatImage out(color.width, color.height, 4);
    for (uint32_t y = 0; y < color.height; ++y)
        for (uint32_t x = 0; x < color.width; ++x) {
            for (uint32_t k = 0; k < 3; ++k) {
                std::array<float, 9> v{};
                size_t n = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) v[n++] = color.clamped(int(x) + dx, int(y) + dy, k);
                std::nth_element(v.begin(), v.begin() + 4, v.end());
                out.at(x, y, k) = v[4];
            }
            out.at(x, y, 3) = color.channels > 3 ? color.at(x, y, 3) : 1.0f;
        }
    return out;
}

} // namespace hush::passes_test::reference
