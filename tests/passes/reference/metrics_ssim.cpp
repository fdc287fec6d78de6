#include "reference/metrics_ssim.hpp"

#include <algorithm>
#include <cmath>

#include "reference/metrics_error_metrics.hpp"

namespace hush::passes_test::reference {

SsimResult ssim(const FloatImage& image, const FloatImage& reference, double k1, double k2, double dynamicRange,
                double sigma) {
    constexpr int radius = 5;   // 11 x 11
    const double c1 = (k1 * dynamicRange) * (k1 * dynamicRange), c2 = (k2 * dynamicRange) * (k2 * dynamicRange);
    const int w = int(image.width), h = int(image.height);
    // Window centres along an axis: the valid ones when the window fits, else all.
    auto first = [&](int n) { return n >= 2 * radius + 1 ? radius : 0; };
    auto last = [&](int n) { return n >= 2 * radius + 1 ? n - 1 - radius : n - 1; };

    SsimResult r;
    r.map = FloatImage(image.width, image.height, 4, 0.0f);
    double total = 0;
    for (int cy = first(h); cy <= last(h); ++cy)
        for (int cx = first(w); cx <= last(w); ++cx) {
            // The 2D Gaussian over the taps inside the image, normalised to unit sum.
            double weightSum = 0;
            bool finite = true;
            for (int y = std::max(0, cy - radius); y <= std::min(h - 1, cy + radius); ++y)
                for (int x = std::max(0, cx - radius); x <= std::min(w - 1, cx + radius); ++x) {
                    const double dx = x - cx, dy = y - cy;
                    weightSum += std::exp(-(dx * dx + dy * dy) / (2 * sigma * sigma));
                    finite = finite && finiteRgb(image, uint32_t(x), uint32_t(y)) &&
                             finiteRgb(reference, uint32_t(x), uint32_t(y));
                }
            if (!finite) {
                ++r.excludedWindows;
                r.map.at(uint32_t(cx), uint32_t(cy), 2) = 1.0f;
                continue;
            }
            double channelMean = 0;
            for (uint32_t c = 0; c < 3; ++c) {
                double muA = 0, muB = 0, aa = 0, bb = 0, ab = 0;
                for (int y = std::max(0, cy - radius); y <= std::min(h - 1, cy + radius); ++y)
                    for (int x = std::max(0, cx - radius); x <= std::min(w - 1, cx + radius); ++x) {
                        const double dx = x - cx, dy = y - cy;
                        const double wt = std::exp(-(dx * dx + dy * dy) / (2 * sigma * sigma)) / weightSum;
                        const double a = image.at(uint32_t(x), uint32_t(y), c);
                        const double b = reference.at(uint32_t(x), uint32_t(y), c);
                        muA += wt * a;
                        muB += wt * b;
                        aa += wt * a * a;
                        bb += wt * b * b;
                        ab += wt * a * b;
                    }
                // Wang et al. 2004, Eq. 13, with the moments of ssim_index.m.
                const double varA = aa - muA * muA, varB = bb - muB * muB, cov = ab - muA * muB;
                channelMean +=
                    (2 * muA * muB + c1) * (2 * cov + c2) / ((muA * muA + muB * muB + c1) * (varA + varB + c2));
            }
            channelMean /= 3.0;
            ++r.windows;
            total += channelMean;
            r.map.at(uint32_t(cx), uint32_t(cy), 0) = float(channelMean);
            r.map.at(uint32_t(cx), uint32_t(cy), 1) = 1.0f;
        }
    r.ssim = r.windows ? total / double(r.windows) : 0.0;
    return r;
}

} // namespace hush::passes_test::reference
