#include "reference/bmfr_accumulate.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "reference/common_reproject.hpp"

namespace hush::passes_test::reference {

FloatImage bmfrAccumulate(const FloatImage& input, const FloatImage& decision, const FloatImage& previous,
                          const passes::BmfrAccumulateSettings& settings, bool historyValid) {
    const uint32_t w = input.width, h = input.height;
    // Sec. 3.1: the count only matters while 1 / n > minWeight; it saturates where it stops mattering.
    const float cap = float(std::ceil(1.0 / double(settings.minWeight) - 1e-5));
    FloatImage out(w, h, 4);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            std::array<float, 4> prev{};
            const bool ok = historyValid && fetchReprojected(previous, decision, x, y, prev);
            if (!ok) {   // disoccluded, first frame, reset: the average restarts at this sample
                for (uint32_t c = 0; c < 3; ++c) out.at(x, y, c) = input.at(x, y, c);
                out.at(x, y, 3) = 1.0f;
                continue;
            }
            // The bilinearly fetched count, rounded to the closest integer (Sec. 3.1).
            const float prevCount = std::round(std::clamp(prev[3], 0.0f, cap));
            const float n = std::min(prevCount + 1.0f, cap);
            const float a = std::max(settings.minWeight, 1.0f / n);
            for (uint32_t c = 0; c < 3; ++c) out.at(x, y, c) = a * input.at(x, y, c) + (1.0f - a) * prev[c];
            out.at(x, y, 3) = n;
        }
    return out;
}

} // namespace hush::passes_test::reference
