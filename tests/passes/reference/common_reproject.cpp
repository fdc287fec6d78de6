#include "reference/common_reproject.hpp"

#include <cmath>
#include <vector>

namespace hush::passes_test::reference {

namespace {
struct Tap {
    int x, y;
    float dx, dy;   // tap centre minus previous position, pixels
};

// SVGF Sec. 4.1's three tests for one tap, in the form of reproject.hpp.
bool sameSurface(const SurfaceImages& cur, const SurfaceImages& prev, uint32_t px, uint32_t py, const Tap& t,
                 const passes::ReprojectSettings& s) {
    if (t.x < 0 || t.y < 0 || t.x >= int(prev.normalDepth.width) || t.y >= int(prev.normalDepth.height)) return false;
    const auto tx = uint32_t(t.x), ty = uint32_t(t.y);
    if (prev.gradientMesh.at(tx, ty, 2) != cur.gradientMesh.at(px, py, 2)) return false;
    float cosine = 0.0f;
    for (uint32_t c = 0; c < 3; ++c) cosine += prev.normalDepth.at(tx, ty, c) * cur.normalDepth.at(px, py, c);
    if (!(cosine >= s.normalCosine)) return false;
    const float z = cur.normalDepth.at(px, py, 3);
    const float slope = std::fabs(cur.gradientMesh.at(px, py, 0)) * std::fabs(t.dx) +
                        std::fabs(cur.gradientMesh.at(px, py, 1)) * std::fabs(t.dy);
    const float tolerance = s.depthSlopeTolerance * slope + s.depthRelativeTolerance * std::fabs(z);
    return std::fabs(prev.normalDepth.at(tx, ty, 3) - z) <= tolerance;
}
} // namespace

FloatImage reproject(const FloatImage& motion, const SurfaceImages& current, const SurfaceImages& previous,
                     const passes::ReprojectSettings& settings, bool historyValid) {
    const uint32_t w = motion.width, h = motion.height;
    FloatImage out(w, h, 4);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            // Previous position of the pixel centre, minus the half-pixel of texel centres.
            const float qx = float(x) + motion.at(x, y, 0);
            const float qy = float(y) + motion.at(x, y, 1);
            const bool onScreenish = qx >= -2.0f && qy >= -2.0f && qx <= float(w) + 1.0f && qy <= float(h) + 1.0f;
            const float sx = std::isnan(qx) ? -2.0f : std::fmin(std::fmax(qx, -2.0f), float(w) + 1.0f);
            const float sy = std::isnan(qy) ? -2.0f : std::fmin(std::fmax(qy, -2.0f), float(h) + 1.0f);
            auto put = [&](float a, float b, uint32_t mask, passes::ReprojectionMode mode) {
                out.at(x, y, 0) = a, out.at(x, y, 1) = b;
                out.at(x, y, 2) = float(mask), out.at(x, y, 3) = float(uint32_t(mode));
            };
            if (!historyValid || !onScreenish || current.gradientMesh.at(x, y, 2) < 0.0f) {
                put(sx, sy, 0, passes::ReprojectionMode::Disoccluded);
                continue;
            }
            const float bx = std::floor(qx), by = std::floor(qy);
            const float fx = qx - bx, fy = qy - by;
            const float weights[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
            uint32_t mask = 0;
            for (uint32_t k = 0; k < 4; ++k) {
                const int i = int(k % 2), j = int(k / 2);
                const Tap tap{int(bx) + i, int(by) + j, float(i) - fx, float(j) - fy};
                if (weights[k] > 0.0f && sameSurface(current, previous, x, y, tap, settings)) mask |= 1u << k;
            }
            if (mask) {
                put(qx, qy, mask, passes::ReprojectionMode::Bilinear);
                continue;
            }
            if (settings.fallback3x3) {
                // Centred on the texel containing the previous position.
                const int cx = int(std::floor(qx + 0.5f)), cy = int(std::floor(qy + 0.5f));
                for (uint32_t k = 0; k < 9; ++k) {
                    const int tx = cx - 1 + int(k % 3), ty = cy - 1 + int(k / 3);
                    const Tap tap{tx, ty, float(tx) - qx, float(ty) - qy};
                    if (sameSurface(current, previous, x, y, tap, settings)) mask |= 1u << k;
                }
                if (mask) {
                    put(float(cx - 1), float(cy - 1), mask, passes::ReprojectionMode::Fallback3x3);
                    continue;
                }
            }
            put(sx, sy, 0, passes::ReprojectionMode::Disoccluded);
        }
    return out;
}

bool fetchReprojected(const FloatImage& history, const FloatImage& decision, uint32_t x, uint32_t y,
                      std::array<float, 4>& value) {
    value = {0, 0, 0, 0};
    const auto mode = uint32_t(decision.at(x, y, 3) + 0.5f);
    const auto mask = uint32_t(decision.at(x, y, 2) + 0.5f);
    if (mode == 0 || mode > 2 || mask == 0) return false;
    const int width = mode == 1 ? 2 : 3;
    const float bx = std::floor(decision.at(x, y, 0)), by = std::floor(decision.at(x, y, 1));
    const float fx = decision.at(x, y, 0) - bx, fy = decision.at(x, y, 1) - by;
    struct Weighted {
        int x, y;
        float w;
    };
    std::vector<Weighted> taps;
    float total = 0.0f;
    for (int k = 0; k < width * width; ++k) {
        if (!(mask & (1u << k))) continue;
        const int i = k % width, j = k / width;
        const float w = mode == 1 ? (i ? fx : 1 - fx) * (j ? fy : 1 - fy) : 1.0f;
        taps.push_back({int(bx) + i, int(by) + j, w});
        total += w;
    }
    // Only usable taps of zero bilinear weight (a decision the pass never makes): equal weights.
    if (!(total > 0.0f)) {
        for (auto& t : taps) t.w = 1.0f;
        total = float(taps.size());
    }
    for (const auto& t : taps)
        for (uint32_t c = 0; c < 4; ++c)
            value[c] += t.w / total * history.at(uint32_t(t.x), uint32_t(t.y), c);
    return true;
}

FloatImage identityDecision(uint32_t width, uint32_t height) {
    FloatImage d(width, height, 4);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            d.at(x, y, 0) = float(x), d.at(x, y, 1) = float(y);
            d.at(x, y, 2) = 1.0f, d.at(x, y, 3) = float(uint32_t(passes::ReprojectionMode::Bilinear));
        }
    return d;
}

} // namespace hush::passes_test::reference
