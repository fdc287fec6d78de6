#include "reference/eaw_atrous.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace hush::passes_test::reference {

namespace {

double b3(int offset) {
    const double h[5] = {1.0 / 16.0, 1.0 / 4.0, 3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0};
    return h[offset + 2];
}

double squaredDistance(const FloatImage& image, uint32_t px, uint32_t py, uint32_t qx, uint32_t qy) {
    double sum = 0.0;
    for (uint32_t c = 0; c < 3; ++c) {
        const double d = double(image.at(px, py, c)) - double(image.at(qx, qy, c));
        sum += d * d;
    }
    return sum;
}

bool hasSurface(const FloatImage& normal, uint32_t x, uint32_t y) {
    double n2 = 0.0;
    for (uint32_t c = 0; c < 3; ++c) n2 += double(normal.at(x, y, c)) * normal.at(x, y, c);
    return n2 > 1e-6;
}

double luminance(const FloatImage& image, uint32_t x, uint32_t y) {
    return std::fabs(0.2126 * image.at(x, y, 0) + 0.7152 * image.at(x, y, 1) + 0.0722 * image.at(x, y, 2));
}

// exp(-d^2 / sigma^2), sigma^2 floored at 1e-30 as the node does.
double edgeStop(double squaredDist, double sigma) {
    return std::exp(-squaredDist / std::max(sigma * sigma, 1e-30));
}

// Calls f(qx, qy, h) for the 5x5 taps at `step` inside the image that have a surface.
template <class F>
void forEachSurfaceTap(const FloatImage& color, const FloatImage& normal, uint32_t x, uint32_t y, int64_t step, F&& f) {
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const int64_t qx = int64_t(x) + dx * step, qy = int64_t(y) + dy * step;
            if (qx < 0 || qy < 0 || qx >= int64_t(color.width) || qy >= int64_t(color.height)) continue;
            if (!hasSurface(normal, uint32_t(qx), uint32_t(qy))) continue;
            f(uint32_t(qx), uint32_t(qy), b3(dx) * b3(dy));
        }
}

} // namespace

FloatImage eawAtrousLevel(const FloatImage& color, const FloatImage& normal, const FloatImage& position,
                          uint32_t level, const passes::EawSettings& s, const FloatImage* depth) {
    FloatImage out(color.width, color.height, 4);
    const int64_t step = int64_t(1) << std::min(level, 40u);
    // Dammertz et al. 2010: the colour sigma halves at every level. hush's default makes
    // it relative to the B3-weighted mean luminance of the level's surface taps.
    const bool relative = s.sigmaRtRelative > 0.0f;
    const double sigmaRtLevel = double(relative ? s.sigmaRtRelative : s.sigmaRt) * std::pow(2.0, -double(level));
    for (uint32_t y = 0; y < color.height; ++y)
        for (uint32_t x = 0; x < color.width; ++x) {
            out.at(x, y, 3) = color.channels > 3 ? color.at(x, y, 3) : 1.0f;
            if (!hasSurface(normal, x, y)) {
                for (uint32_t c = 0; c < 3; ++c) out.at(x, y, c) = color.at(x, y, c);
                continue;
            }
            // With depth: ||x_p - x_q|| / z_p against sigmaXRelative.
            const double zP = depth ? std::max(std::fabs(double(depth->at(x, y))), 1e-20) : 1.0;
            const double sigmaX = depth ? double(s.sigmaXRelative) * zP : double(s.sigmaX);
            double sigmaRt = sigmaRtLevel;
            if (relative) {
                double mean = 0.0, weights = 0.0;
                forEachSurfaceTap(color, normal, x, y, step, [&](uint32_t qx, uint32_t qy, double h) {
                    mean += h * luminance(color, qx, qy);
                    weights += h;
                });
                sigmaRt *= std::max(mean / weights, 1e-20);
            }
            double sum[3] = {0.0, 0.0, 0.0}, weightSum = 0.0;
            forEachSurfaceTap(color, normal, x, y, step, [&](uint32_t qx, uint32_t qy, double h) {
                const double w = edgeStop(squaredDistance(color, x, y, qx, qy), sigmaRt) *
                                 edgeStop(squaredDistance(normal, x, y, qx, qy), double(s.sigmaN)) *
                                 edgeStop(squaredDistance(position, x, y, qx, qy), sigmaX);
                for (uint32_t c = 0; c < 3; ++c) sum[c] += h * w * color.at(qx, qy, c);
                weightSum += h * w;
            });
            for (uint32_t c = 0; c < 3; ++c) out.at(x, y, c) = float(sum[c] / weightSum);
        }
    return out;
}

std::vector<FloatImage> eawAtrousLevels(const FloatImage& color, const FloatImage& normal,
                                        const FloatImage& position, const passes::EawSettings& s) {
    std::vector<FloatImage> levels;
    levels.reserve(s.iterations);   // `current` points into it
    const FloatImage* current = &color;
    for (uint32_t i = 0; i < s.iterations; ++i) {
        levels.push_back(eawAtrousLevel(*current, normal, position, i, s));
        current = &levels.back();
    }
    return levels;
}

} // namespace hush::passes_test::reference
