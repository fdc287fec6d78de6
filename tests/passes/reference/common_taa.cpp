#include "reference/common_taa.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace hush::passes_test::reference {

namespace {

using Vec3 = std::array<double, 3>;

// Malvar & Sullivan's YCoCg: Y = (R + 2G + B) / 4, Co = (R - B) / 2, Cg = (2G - R - B) / 4.
Vec3 toYCoCg(const Vec3& c) {
    return {(c[0] + 2.0 * c[1] + c[2]) / 4.0, (c[0] - c[2]) / 2.0, (2.0 * c[1] - c[0] - c[2]) / 4.0};
}

// Inverse: G = Y + Cg, R = Y - Cg + Co, B = Y - Cg - Co.
Vec3 fromYCoCg(const Vec3& c) { return {c[0] - c[2] + c[1], c[0] + c[2], c[0] - c[2] - c[1]}; }

Vec3 rgbAt(const FloatImage& image, int x, int y) {
    return {double(image.clamped(x, y, 0)), double(image.clamped(x, y, 1)), double(image.clamped(x, y, 2))};
}

// Bilinear at continuous position (px, py), texel centres at +0.5, edges repeated.
Vec3 bilinear(const FloatImage& image, double px, double py) {
    const double u = px - 0.5, v = py - 0.5;
    const int x0 = int(std::floor(u)), y0 = int(std::floor(v));
    const double fx = u - x0, fy = v - y0;
    Vec3 out{};
    const Vec3 c00 = rgbAt(image, x0, y0), c10 = rgbAt(image, x0 + 1, y0);
    const Vec3 c01 = rgbAt(image, x0, y0 + 1), c11 = rgbAt(image, x0 + 1, y0 + 1);
    for (int c = 0; c < 3; ++c)
        out[c] = (1 - fy) * ((1 - fx) * c00[c] + fx * c10[c]) + fy * ((1 - fx) * c01[c] + fx * c11[c]);
    return out;
}

// Keys 1981 cubic convolution kernel with a = -0.5 (the Catmull-Rom spline):
// (a + 2)|s|^3 - (a + 3)|s|^2 + 1 for |s| <= 1, a|s|^3 - 5a|s|^2 + 8a|s| - 4a for
// 1 < |s| < 2, 0 beyond; s = distance from the sample point to a texel centre.
double catmullRomKernel(double s) {
    const double a = -0.5;
    s = std::abs(s);
    if (s <= 1.0) return (a + 2.0) * s * s * s - (a + 3.0) * s * s + 1.0;
    if (s < 2.0) return a * s * s * s - 5.0 * a * s * s + 8.0 * a * s - 4.0 * a;
    return 0.0;
}

// Separable Catmull-Rom at (px, py) over the 4x4 texels around it, edges repeated.
Vec3 catmullRom(const FloatImage& image, double px, double py) {
    const double u = px - 0.5, v = py - 0.5;
    const int x0 = int(std::floor(u)), y0 = int(std::floor(v));
    Vec3 out{};
    for (int j = -1; j <= 2; ++j)
        for (int i = -1; i <= 2; ++i) {
            const double w = catmullRomKernel(u - (x0 + i)) * catmullRomKernel(v - (y0 + j));
            const Vec3 c = rgbAt(image, x0 + i, y0 + j);
            for (size_t k = 0; k < 3; ++k) out[k] += w * c[k];
        }
    return out;
}

Vec3 resampleHistory(const FloatImage& history, double px, double py, passes::TaaHistoryFilter filter) {
    return filter == passes::TaaHistoryFilter::CatmullRom ? catmullRom(history, px, py) : bilinear(history, px, py);
}

// What a reprojection decision (reproject.hpp) says of one pixel's history.
struct DecidedHistory {
    bool disoccluded = true;
    bool whole = false;   // 2x2 footprint whose usable taps are exactly those of positive bilinear weight
    Vec3 footprint{};     // the usable taps, renormalised (when not disoccluded)
};

DecidedHistory decide(const FloatImage& history, const FloatImage& decision, uint32_t x, uint32_t y) {
    DecidedHistory d;
    const double bx = std::floor(double(decision.at(x, y, 0))), by = std::floor(double(decision.at(x, y, 1)));
    const double fx = decision.at(x, y, 0) - bx, fy = decision.at(x, y, 1) - by;
    const auto mask = uint32_t(std::lround(decision.at(x, y, 2)));
    const auto mode = uint32_t(std::lround(decision.at(x, y, 3)));
    if (mask == 0 || (mode != 1 && mode != 2)) return d;
    const int width = mode == 1 ? 2 : 3;
    double weightSum = 0.0;
    bool whole = mode == 1;
    for (int j = 0; j < width; ++j)
        for (int i = 0; i < width; ++i) {
            // 2x2: bilinear weights; 3x3: equal weights.
            const double w = mode == 1 ? (i == 0 ? 1.0 - fx : fx) * (j == 0 ? 1.0 - fy : fy) : 1.0;
            const bool usable = (mask >> uint32_t(j * width + i)) & 1u;
            // Whole: the usable taps are exactly those of positive weight.
            if (mode == 1 && (w > 0.0) != usable) whole = false;
            if (!usable || w <= 0.0) continue;
            const Vec3 c = rgbAt(history, int(bx) + i, int(by) + j);
            for (size_t k = 0; k < 3; ++k) d.footprint[k] += w * c[k];
            weightSum += w;
        }
    if (!(weightSum > 0.0)) return d;
    for (auto& v : d.footprint) v /= weightSum;
    d.disoccluded = false;
    d.whole = whole;
    return d;
}

struct Box {
    Vec3 lo, hi, centre;
};

Box neighbourhood(const FloatImage& current, int x, int y, const passes::TaaSettings& s) {
    std::array<Vec3, 9> n;
    int k = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) n[size_t(k++)] = toYCoCg(rgbAt(current, x + dx, y + dy));
    Box box;
    for (int c = 0; c < 3; ++c) {
        if (s.box == passes::TaaBox::Variance) {
            double mean = 0.0;
            for (const auto& v : n) mean += v[size_t(c)] / 9.0;
            double var = 0.0;
            for (const auto& v : n) var += (v[size_t(c)] - mean) * (v[size_t(c)] - mean) / 9.0;
            const double half = std::max(double(s.varianceGamma), 0.0) * std::sqrt(var);
            box.lo[size_t(c)] = mean - half;
            box.hi[size_t(c)] = mean + half;
            box.centre[size_t(c)] = mean;
        } else {
            double lo = n[0][size_t(c)], hi = lo;
            for (const auto& v : n) lo = std::min(lo, v[size_t(c)]), hi = std::max(hi, v[size_t(c)]);
            box.lo[size_t(c)] = lo;
            box.hi[size_t(c)] = hi;
            box.centre[size_t(c)] = (lo + hi) / 2.0;
        }
    }
    return box;
}

// Largest t in [0, 1] with centre + t (h - centre) inside the box, a component
// counting as inside up to 2^-16 of the box's largest |component| (taa.comp: the
// margin keeps rounding from clipping a history that lies on a flat box's face).
Vec3 clip(const Vec3& h, const Box& b) {
    double extent = 0.0;
    for (size_t c = 0; c < 3; ++c) extent = std::max({extent, std::abs(b.lo[c]), std::abs(b.hi[c])});
    const double margin = extent / 65536.0;
    double t = 1.0;
    for (size_t c = 0; c < 3; ++c) {
        const double v = h[c] - b.centre[c];
        if (h[c] > b.hi[c] + margin && v > 0.0) t = std::min(t, (b.hi[c] - b.centre[c]) / v);
        if (h[c] < b.lo[c] - margin && v < 0.0) t = std::min(t, (b.lo[c] - b.centre[c]) / v);
    }
    Vec3 out;
    for (size_t c = 0; c < 3; ++c) out[c] = b.centre[c] + t * (h[c] - b.centre[c]);
    return out;
}

} // namespace

FloatImage Taa::frame(const FloatImage& current, const FloatImage& motion, const FloatImage& decision) {
    FloatImage out(current.width, current.height, 4, 1.0f);
    const double alpha = std::clamp(double(settings_.alpha), 0.0, 1.0);
    for (uint32_t y = 0; y < out.height; ++y)
        for (uint32_t x = 0; x < out.width; ++x) {
            const Vec3 cur = rgbAt(current, int(x), int(y));
            // Previous position of this pixel's centre.
            const double px = x + 0.5 + motion.at(x, y, 0), py = y + 0.5 + motion.at(x, y, 1);
            const bool onScreen = px >= 0.0 && py >= 0.0 && px < double(out.width) && py < double(out.height);
            // The history: through the decision if there is one, else through the motion.
            bool haveHistory = false;
            Vec3 hist{};
            if (hasHistory_) {
                const DecidedHistory d =
                    decision.pixels.empty() ? DecidedHistory{false, true, {}} : decide(history_, decision, x, y);
                if (!d.disoccluded && !d.whole) {
                    hist = d.footprint;
                    haveHistory = true;
                } else if (!d.disoccluded && onScreen) {
                    hist = resampleHistory(history_, px, py, settings_.historyFilter);
                    haveHistory = true;
                }
            }
            Vec3 result = cur;
            if (haveHistory) {
                const Box box = neighbourhood(current, int(x), int(y), settings_);
                Vec3 h = toYCoCg(hist);
                if (settings_.rectify == passes::TaaRectify::Clip) {
                    h = clip(h, box);
                } else {
                    for (size_t c = 0; c < 3; ++c) h[c] = std::clamp(h[c], box.lo[c], box.hi[c]);
                }
                const Vec3 rgb = fromYCoCg(h);
                for (size_t c = 0; c < 3; ++c) result[c] = std::max(rgb[c] + alpha * (cur[c] - rgb[c]), 0.0);
            }
            for (uint32_t c = 0; c < 3; ++c) out.at(x, y, c) = float(result[c]);
        }
    history_ = out;
    hasHistory_ = true;
    return out;
}

} // namespace hush::passes_test::reference
