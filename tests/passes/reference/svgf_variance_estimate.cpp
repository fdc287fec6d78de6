#include "reference/svgf_variance_estimate.hpp"

#include <algorithm>
#include <cmath>

namespace hush::passes_test::reference {

FloatImage svgfVariance(const SvgfTemporalImages& t, const SurfaceImages& surface,
                        const passes::SvgfVarianceSettings& s) {
    const uint32_t w = t.color.width, h = t.color.height;
    FloatImage out(w, h, 4);
    const int radius = std::clamp(s.radius, 0, 16);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const float n = std::max(t.moments.at(x, y, 2), 1.0f);
            if (n >= s.minHistoryLength) {
                for (uint32_t c = 0; c < 3; ++c) out.at(x, y, c) = t.color.at(x, y, c);
                const float m1 = t.moments.at(x, y, 0), m2 = t.moments.at(x, y, 1);
                out.at(x, y, 3) = std::max(0.0f, m2 - m1 * m1);
                continue;
            }
            // Short history: 7x7 bilateral (Sec. 4.2) with Eq. 3 and 4 weights.
            double sumW = 0, sumC[3] = {0, 0, 0}, sumM[2] = {0, 0};
            for (int dy = -radius; dy <= radius; ++dy)
                for (int dx = -radius; dx <= radius; ++dx) {
                    const int qx = int(x) + dx, qy = int(y) + dy;
                    if (qx < 0 || qy < 0 || qx >= int(w) || qy >= int(h)) continue;
                    const auto ux = uint32_t(qx), uy = uint32_t(qy);
                    double weight = 1.0;
                    if (dx != 0 || dy != 0) {
                        const double gradDotOffset = double(surface.gradientMesh.at(x, y, 0)) * dx +
                                                     double(surface.gradientMesh.at(x, y, 1)) * dy;
                        const double denom =
                            std::max(double(s.sigmaZ) * std::fabs(gradDotOffset) + s.depthEpsilon, 1e-30);
                        const double dz = std::fabs(double(surface.normalDepth.at(x, y, 3)) -
                                                    surface.normalDepth.at(ux, uy, 3));
                        double cosine = 0;
                        for (uint32_t c = 0; c < 3; ++c)
                            cosine += double(surface.normalDepth.at(x, y, c)) * surface.normalDepth.at(ux, uy, c);
                        weight = std::exp(-dz / denom) * std::pow(std::max(0.0, cosine), double(s.sigmaN));
                    }
                    sumW += weight;
                    for (uint32_t c = 0; c < 3; ++c) sumC[c] += weight * t.color.at(ux, uy, c);
                    sumM[0] += weight * t.moments.at(ux, uy, 0);
                    sumM[1] += weight * t.moments.at(ux, uy, 1);
                }
            for (uint32_t c = 0; c < 3; ++c) out.at(x, y, c) = float(sumC[c] / sumW);
            const double m1 = sumM[0] / sumW, m2 = sumM[1] / sumW;
            double variance = std::max(0.0, m2 - m1 * m1);
            if (s.shortHistoryBoost) variance *= double(s.minHistoryLength) / n;
            out.at(x, y, 3) = float(variance);
        }
    return out;
}

} // namespace hush::passes_test::reference
