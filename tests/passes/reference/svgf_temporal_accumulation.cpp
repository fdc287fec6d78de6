#include "reference/svgf_temporal_accumulation.hpp"

#include <algorithm>
#include <array>

#include "reference/common_reproject.hpp"

namespace hush::passes_test::reference {

float luminance(float r, float g, float b) { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }

SvgfTemporalImages svgfTemporal(const FloatImage& illumination, const FloatImage& decision,
                                const SvgfTemporalImages& previous, const passes::SvgfTemporalSettings& s,
                                bool historyValid) {
    const uint32_t w = illumination.width, h = illumination.height;
    SvgfTemporalImages out{FloatImage(w, h, 4, 1.0f), FloatImage(w, h, 4)};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const float r = illumination.at(x, y, 0), g = illumination.at(x, y, 1), b = illumination.at(x, y, 2);
            const float l = std::clamp(luminance(r, g, b), -1e18f, 1e18f);
            std::array<float, 4> prevC{}, prevM{};
            const bool ok = historyValid && fetchReprojected(previous.color, decision, x, y, prevC) &&
                            fetchReprojected(previous.moments, decision, x, y, prevM);
            // Disocclusion: n = 1, i.e. alpha = 1: the sample alone.
            const float n = ok ? std::min(std::max(prevM[2], 0.0f) + 1.0f, std::max(s.maxHistoryLength, 1.0f)) : 1.0f;
            const float a = ok ? std::max(s.alpha, 1.0f / n) : 1.0f;
            const float am = ok ? std::max(s.momentsAlpha, 1.0f / n) : 1.0f;
            const float cur[3] = {r, g, b};
            for (uint32_t c = 0; c < 3; ++c) out.color.at(x, y, c) = ok ? a * cur[c] + (1 - a) * prevC[c] : cur[c];
            out.moments.at(x, y, 0) = ok ? am * l + (1 - am) * prevM[0] : l;
            out.moments.at(x, y, 1) = ok ? am * l * l + (1 - am) * prevM[1] : l * l;
            out.moments.at(x, y, 2) = n;
        }
    return out;
}

} // namespace hush::passes_test::reference
