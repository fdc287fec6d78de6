#include "reference/mara_temporal.hpp"

#include <algorithm>
#include <cmath>

namespace hush::passes_test::reference {

namespace {

struct Vec3 {
    double x = 0, y = 0, z = 0;
};

Vec3 rgb(const FloatImage& image, int x, int y) {
    return {image.at(uint32_t(x), uint32_t(y), 0), image.at(uint32_t(x), uint32_t(y), 1),
            image.at(uint32_t(x), uint32_t(y), 2)};
}

bool inside(const FloatImage& image, int x, int y) {
    return x >= 0 && y >= 0 && x < int(image.width) && y < int(image.height);
}

double confidence(const MaraTemporalParams& p, double metres) {
    const double t = std::clamp((metres - p.d0) / std::max(p.d1 - p.d0, 1e-12), 0.0, 1.0);
    return p.hysteresis * (1.0 - t * t * (3.0 - 2.0 * t));
}

// The blend at (x, y) with last frame's sample at pixel position (qx, qy), or none.
void blend(const FloatImage& current, const FloatImage& history, const FloatImage& positionHistory, int x, int y,
           bool reprojected, double qx, double qy, Vec3 expected, const MaraTemporalParams& p, FloatImage& out) {
    const Vec3 c = rgb(current, x, y);
    Vec3 lo = c, hi = c;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = std::clamp(x + dx, 0, int(current.width) - 1), ny = std::clamp(y + dy, 0, int(current.height) - 1);
            const Vec3 n = rgb(current, nx, ny);
            lo = {std::min(lo.x, n.x), std::min(lo.y, n.y), std::min(lo.z, n.z)};
            hi = {std::max(hi.x, n.x), std::max(hi.y, n.y), std::max(hi.z, n.z)};
        }
    double result[3] = {c.x, c.y, c.z}, conf = 0.0;
    if (reprojected) {
        const double bx = std::floor(qx - 0.5), by = std::floor(qy - 0.5);
        const double fx = qx - 0.5 - bx, fy = qy - 0.5 - by;
        Vec3 h, pos;
        double sum = 0.0;
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                const int tx = int(bx) + i, ty = int(by) + j;
                if (!inside(current, tx, ty)) continue;
                const double w = (i ? fx : 1.0 - fx) * (j ? fy : 1.0 - fy);
                const Vec3 th = rgb(history, tx, ty), tp = rgb(positionHistory, tx, ty);
                h = {h.x + w * th.x, h.y + w * th.y, h.z + w * th.z};
                pos = {pos.x + w * tp.x, pos.y + w * tp.y, pos.z + w * tp.z};
                sum += w;
            }
        if (sum > 0.0) {
            const double dx = expected.x - pos.x / sum, dy = expected.y - pos.y / sum, dz = expected.z - pos.z / sum;
            conf = confidence(p, std::sqrt(dx * dx + dy * dy + dz * dz) * p.metresPerUnit);
            const double hc[3] = {std::clamp(h.x / sum, lo.x, hi.x), std::clamp(h.y / sum, lo.y, hi.y),
                                  std::clamp(h.z / sum, lo.z, hi.z)};
            for (int k = 0; k < 3; ++k) result[k] += (hc[k] - result[k]) * p.hysteresis * conf;
        }
    }
    for (int k = 0; k < 3; ++k) out.at(uint32_t(x), uint32_t(y), uint32_t(k)) = float(result[k]);
    out.at(uint32_t(x), uint32_t(y), 3) = float(conf);
}

} // namespace

FloatImage maraMatteTemporal(const FloatImage& current, const FloatImage& motion, const FloatImage& position,
                             const FloatImage& history, const FloatImage& positionHistory,
                             const MaraTemporalParams& params) {
    FloatImage out(current.width, current.height, 4);
    for (int y = 0; y < int(out.height); ++y)
        for (int x = 0; x < int(out.width); ++x) {
            const double qx = x + 0.5 + motion.at(uint32_t(x), uint32_t(y), 0);
            const double qy = y + 0.5 + motion.at(uint32_t(x), uint32_t(y), 1);
            const bool in = qx >= 0 && qy >= 0 && qx < out.width && qy < out.height;
            blend(current, history, positionHistory, x, y, params.historyValid && in, qx, qy, rgb(position, x, y),
                  params, out);
        }
    return out;
}

FloatImage maraGlossyTemporal(const FloatImage& current, const FloatImage& virtualpos, const FloatImage& history,
                              const FloatImage& virtualposHistory, const std::array<double, 16>& m,
                              const MaraTemporalParams& params) {
    FloatImage out(current.width, current.height, 4);
    for (int y = 0; y < int(out.height); ++y)
        for (int x = 0; x < int(out.width); ++x) {
            const Vec3 v = rgb(virtualpos, x, y);
            double clip[4];
            for (int r = 0; r < 4; ++r) clip[r] = m[size_t(r)] * v.x + m[size_t(4 + r)] * v.y + m[size_t(8 + r)] * v.z + m[size_t(12 + r)];
            const bool front = clip[3] > 1e-6;
            const double w = std::max(clip[3], 1e-6);
            const double qx = (clip[0] / w * 0.5 + 0.5) * out.width, qy = (clip[1] / w * 0.5 + 0.5) * out.height;
            const bool in = front && qx >= 0 && qy >= 0 && qx < out.width && qy < out.height;
            blend(current, history, virtualposHistory, x, y, params.historyValid && in, qx, qy, v, params, out);
        }
    return out;
}

} // namespace hush::passes_test::reference
