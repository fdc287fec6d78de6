#include "reference/mara_sparse_bilateral.hpp"

#include <cmath>

namespace hush::passes_test::reference {

namespace {
constexpr double kTwoPi = 6.283185307179586;

bool hasSurface(const FloatImage& normalDepth, uint32_t x, uint32_t y) {
    double n2 = 0.0;
    for (uint32_t k = 0; k < 3; ++k) n2 += double(normalDepth.at(x, y, k)) * normalDepth.at(x, y, k);
    return n2 > 1e-6;
}
} // namespace

uint32_t pcgHash(uint32_t v) {
    const uint32_t state = v * 747796405u + 2891336453u;
    const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

float maraSpiralRotation(uint32_t x, uint32_t y, uint32_t frame) {
    return float(pcgHash(x + pcgHash(y + pcgHash(frame)))) * (1.0f / 4294967296.0f);
}

void maraSpiralOffset(uint32_t i, const MaraBilateralParams& p, double radius, double rotation, double offset[2]) {
    const double a = (double(i) + 0.5) / double(p.taps);
    const double angle = kTwoPi * (p.spiralTurns * a + rotation);
    offset[0] = radius * a * std::cos(angle);
    offset[1] = radius * a * std::sin(angle);
}

double maraGeometryWeight(const FloatImage& nd, const FloatImage& position, uint32_t px, uint32_t py, uint32_t qx,
                          uint32_t qy, double planeSigma, double normalPower) {
    if (!hasSurface(nd, qx, qy)) return 0.0;
    double plane = 0.0, facing = 0.0;
    for (uint32_t k = 0; k < 3; ++k) {
        plane += double(nd.at(px, py, k)) * (double(position.at(qx, qy, k)) - position.at(px, py, k));
        facing += double(nd.at(px, py, k)) * nd.at(qx, qy, k);
    }
    plane = std::fabs(plane) / std::max(planeSigma * nd.at(px, py, 3), 1e-30);
    return std::exp(-std::min(plane * plane, 80.0)) * std::pow(std::max(facing, 0.0), normalPower);
}

MaraBilateralResult maraSparseBilateral(const FloatImage& color, const FloatImage& nd, const FloatImage& position,
                                        const FloatImage* radius, double fixedRadius, uint32_t frame,
                                        const MaraBilateralParams& params) {
    const uint32_t w = color.width, h = color.height;
    MaraBilateralResult out{FloatImage(w, h, 4), std::vector<bool>(size_t(w) * h, false)};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const double r = radius ? radius->at(x, y) : fixedRadius;
            double sum[3] = {color.at(x, y, 0), color.at(x, y, 1), color.at(x, y, 2)};
            double weights = 1.0;
            if (hasSurface(nd, x, y) && r > 0.0) {
                const double rotation = maraSpiralRotation(x, y, frame);
                for (uint32_t i = 0; i < params.taps; ++i) {
                    double o[2];
                    maraSpiralOffset(i, params, r, rotation, o);
                    for (double v : o)
                        if (std::fabs(v - std::floor(v) - 0.5) < 2e-4) out.ambiguous[size_t(y) * w + x] = true;
                    const int64_t qx = int64_t(x) + int64_t(std::floor(o[0] + 0.5));
                    const int64_t qy = int64_t(y) + int64_t(std::floor(o[1] + 0.5));
                    if ((qx == x && qy == y) || qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                    const double g = std::exp(-(o[0] * o[0] + o[1] * o[1]) * 2.0 / (r * r));
                    const double wt = g * maraGeometryWeight(nd, position, x, y, uint32_t(qx), uint32_t(qy),
                                                             params.planeSigma, params.normalPower);
                    for (uint32_t k = 0; k < 3; ++k) sum[k] += wt * color.at(uint32_t(qx), uint32_t(qy), k);
                    weights += wt;
                }
            }
            for (uint32_t k = 0; k < 3; ++k) out.filtered.at(x, y, k) = float(sum[k] / weights);
            out.filtered.at(x, y, 3) = color.channels > 3 ? color.at(x, y, 3) : 1.0f;
        }
    return out;
}

} // namespace hush::passes_test::reference
