#include "reference/svgf_atrous.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace hush::passes_test::reference {

namespace {

// B3 spline (1/16, 1/4, 3/8, 1/4, 1/16): Sec. 4.3, after Eq. 1.
double b3(int offset) {
    switch (offset) {
    case -2:
    case 2: return 1.0 / 16.0;
    case -1:
    case 1: return 1.0 / 4.0;
    default: return 3.0 / 8.0;
    }
}

double luminance(const FloatImage& image, int x, int y) {
    return 0.2126 * image.at(uint32_t(x), uint32_t(y), 0) + 0.7152 * image.at(uint32_t(x), uint32_t(y), 1) +
           0.0722 * image.at(uint32_t(x), uint32_t(y), 2);
}

bool inside(const FloatImage& image, int64_t x, int64_t y) {
    return x >= 0 && y >= 0 && x < int64_t(image.width) && y < int64_t(image.height);
}

bool surfaceAt(const SurfaceImages& s, int x, int y) {
    const auto ux = uint32_t(x), uy = uint32_t(y);
    double n2 = 0.0;
    for (uint32_t c = 0; c < 3; ++c) n2 += double(s.normalDepth.at(ux, uy, c)) * s.normalDepth.at(ux, uy, c);
    return s.gradientMesh.at(ux, uy, 2) >= 0.0f && n2 > 1e-6;
}

// Eq. 3: depth relative to the centre's screen-space depth plane.
double depthWeight(const SurfaceImages& s, int px, int py, int qx, int qy, int64_t ox, int64_t oy,
                   const passes::SvgfAtrousSettings& set) {
    const double zp = s.normalDepth.at(uint32_t(px), uint32_t(py), 3);
    const double zq = s.normalDepth.at(uint32_t(qx), uint32_t(qy), 3);
    const double gx = s.gradientMesh.at(uint32_t(px), uint32_t(py), 0);
    const double gy = s.gradientMesh.at(uint32_t(px), uint32_t(py), 1);
    const double eps = std::max(double(set.depthEpsilon) * std::fabs(zp), 1e-20);
    const double planeDistance = std::fabs(gx * double(ox) + gy * double(oy));
    return std::exp(-std::fabs(zp - zq) / (double(set.sigmaZ) * planeDistance + eps));
}

// Eq. 4.
double normalWeight(const SurfaceImages& s, int px, int py, int qx, int qy, const passes::SvgfAtrousSettings& set) {
    double cosine = 0.0;
    for (uint32_t c = 0; c < 3; ++c)
        cosine += double(s.normalDepth.at(uint32_t(px), uint32_t(py), c)) *
                  s.normalDepth.at(uint32_t(qx), uint32_t(qy), c);
    cosine = std::min(cosine, 1.0);
    return cosine > 0.0 ? std::pow(cosine, double(set.sigmaN)) : 0.0;
}

} // namespace

FloatImage svgfAtrousLevel(const FloatImage& in, const FloatImage& prefiltered, const SurfaceImages& surface,
                           uint32_t level, const passes::SvgfAtrousSettings& set) {
    FloatImage out(in.width, in.height, 4);
    const int64_t step = level < 40 ? (int64_t(1) << level) : (int64_t(1) << 40);
    for (int y = 0; y < int(in.height); ++y)
        for (int x = 0; x < int(in.width); ++x) {
            const auto ux = uint32_t(x), uy = uint32_t(y);
            if (!surfaceAt(surface, x, y)) {
                for (uint32_t c = 0; c < 3; ++c) out.at(ux, uy, c) = in.at(ux, uy, c);
                out.at(ux, uy, 3) = std::max(in.at(ux, uy, 3), 0.0f);
                continue;
            }
            const double lumP = luminance(in, x, y);
            const double sigmaLum =
                double(set.sigmaL) * std::sqrt(std::max(double(prefiltered.at(ux, uy)), 0.0)) +
                double(set.luminanceEpsilon);
            double colour[3] = {0.0, 0.0, 0.0}, weightSum = 0.0, varianceSum = 0.0;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    const int64_t ox = dx * step, oy = dy * step;
                    if (!inside(in, x + ox, y + oy)) continue;
                    const int qx = int(x + ox), qy = int(y + oy);
                    double w = 1.0;
                    if (dx != 0 || dy != 0) {
                        if (!surfaceAt(surface, qx, qy)) continue;
                        const double wl = std::exp(-std::fabs(lumP - luminance(in, qx, qy)) / sigmaLum);   // Eq. 5
                        w = depthWeight(surface, x, y, qx, qy, ox, oy, set) *
                            normalWeight(surface, x, y, qx, qy, set) * wl;
                    }
                    const double hw = b3(dx) * b3(dy) * w;
                    for (uint32_t c = 0; c < 3; ++c) colour[c] += hw * in.at(uint32_t(qx), uint32_t(qy), c);
                    weightSum += hw;
                    varianceSum += hw * hw * std::max(double(in.at(uint32_t(qx), uint32_t(qy), 3)), 0.0);
                }
            for (uint32_t c = 0; c < 3; ++c) out.at(ux, uy, c) = float(colour[c] / weightSum);
            out.at(ux, uy, 3) = float(std::min(varianceSum / (weightSum * weightSum),
                                               double(std::numeric_limits<float>::max())));
        }
    return out;
}

std::vector<FloatImage> svgfAtrousLevels(const FloatImage& illumVariance, const SurfaceImages& surface,
                                         const passes::SvgfAtrousSettings& s) {
    std::vector<FloatImage> levels;
    levels.reserve(s.iterations);   // `current` points into it
    const FloatImage* current = &illumVariance;
    for (uint32_t i = 0; i < s.iterations; ++i) {
        levels.push_back(svgfAtrousLevel(*current, svgfVariancePrefilter(*current), surface, i, s));
        current = &levels.back();
    }
    return levels;
}

} // namespace hush::passes_test::reference
