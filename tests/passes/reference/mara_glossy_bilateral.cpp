#include "reference/mara_glossy_bilateral.hpp"

#include <algorithm>
#include <cmath>

#include "reference/mara_sparse_bilateral.hpp"

namespace hush::passes_test::reference {

FloatImage maraGlossyBilateral(const FloatImage& color, const FloatImage& roughness, const FloatImage& nd,
                               const FloatImage& position, bool vertical, const MaraGlossyBilateralParams& p) {
    const int w = int(color.width), h = int(color.height);
    FloatImage out(color.width, color.height, 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double sum[3] = {color.at(uint32_t(x), uint32_t(y), 0), color.at(uint32_t(x), uint32_t(y), 1),
                             color.at(uint32_t(x), uint32_t(y), 2)};
            double weights = 1.0;
            const double n2 = double(nd.at(uint32_t(x), uint32_t(y), 0)) * nd.at(uint32_t(x), uint32_t(y), 0) +
                              double(nd.at(uint32_t(x), uint32_t(y), 1)) * nd.at(uint32_t(x), uint32_t(y), 1) +
                              double(nd.at(uint32_t(x), uint32_t(y), 2)) * nd.at(uint32_t(x), uint32_t(y), 2);
            if (n2 > 1e-6) {
                const double alpha = std::max(double(roughness.at(uint32_t(x), uint32_t(y))), 0.0);
                const double sigma = p.sigmaScale * std::pow(alpha, p.roughnessExponent) + p.sigmaEpsilon;
                const int r = std::min(int(std::ceil(3.0 * sigma)), 32);
                for (int k = -r; k <= r; ++k) {
                    const int qx = vertical ? x : x + k, qy = vertical ? y + k : y;
                    if (k == 0 || qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                    const double wt = std::exp(-double(k) * k / (2.0 * sigma * sigma)) *
                                      maraGeometryWeight(nd, position, uint32_t(x), uint32_t(y), uint32_t(qx),
                                                         uint32_t(qy), p.planeSigma, p.normalPower);
                    for (uint32_t c = 0; c < 3; ++c) sum[c] += wt * color.at(uint32_t(qx), uint32_t(qy), c);
                    weights += wt;
                }
            }
            for (uint32_t c = 0; c < 3; ++c) out.at(uint32_t(x), uint32_t(y), c) = float(sum[c] / weights);
            out.at(uint32_t(x), uint32_t(y), 3) = color.channels > 3 ? color.at(uint32_t(x), uint32_t(y), 3) : 1.0f;
        }
    return out;
}

} // namespace hush::passes_test::reference
