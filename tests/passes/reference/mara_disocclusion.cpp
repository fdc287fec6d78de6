#include "reference/mara_disocclusion.hpp"

#include <algorithm>

namespace hush::passes_test::reference {

FloatImage maraDisocclusion(const FloatImage& temporal, int R, double lowConfidence, double lowConfidenceScale) {
    const int w = int(temporal.width), h = int(temporal.height);
    FloatImage out(temporal.width, temporal.height, 1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double m = temporal.at(uint32_t(x), uint32_t(y), 3);
            for (int qy = std::max(0, y - R); qy <= std::min(h - 1, y + R); ++qy)
                for (int qx = std::max(0, x - R); qx <= std::min(w - 1, x + R); ++qx)
                    m = std::min(m, double(temporal.at(uint32_t(qx), uint32_t(qy), 3)));
            double r = (1.0 - std::clamp(m, 0.0, 1.0)) * R;
            if (temporal.at(uint32_t(x), uint32_t(y), 3) < lowConfidence) r *= lowConfidenceScale;
            out.at(uint32_t(x), uint32_t(y)) = float(r);
        }
    return out;
}

} // namespace hush::passes_test::reference
