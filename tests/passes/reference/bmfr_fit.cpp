#include "reference/bmfr_fit.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace hush::passes_test::reference {

namespace {

using passes::BmfrFeature;

constexpr float kFloatMax = 3.0e38f;
// The fit's guards, written here rather than taken from passes/bmfr/fit.hpp, so that
// a change to the production values fails this comparison instead of moving the
// reference with it (docs/passes/bmfr-fit.md gives each value and why).
constexpr float kFlatRange = 1e-6f;         // a feature whose block range is below this is flat
constexpr float kDiagonalGuard = 1e-5f;     // back substitution skips |R_kk| below this * max
constexpr float kDependentColumn = 3e-5f;   // the GPU's rank test on a column's norm
constexpr float kZeroColumn = 1e-18f;       // a column of norm below this is zero

// The block grid (Sec. 6.1): blocks of blockSize, shifted each frame by one of the
// 16 offsets, which are data (in 1/64 of a block) and so taken from production; the
// arithmetic of the grid is done here.
struct Grid {
    uint32_t offsetX = 0, offsetY = 0, blocksX = 0, blocksY = 0;
};

Grid blockGrid(uint32_t width, uint32_t height, const passes::BmfrFitSettings& s, uint64_t frameIndex) {
    Grid g;
    if (s.offsetBlocks) {
        const auto o = passes::bmfrOffset64(uint32_t(frameIndex % 16));
        g.offsetX = o[0] * s.blockSize / 64;
        g.offsetY = o[1] * s.blockSize / 64;
    }
    // Blocks start at -offset; enough of them to reach the last pixel.
    g.blocksX = (width + g.offsetX + s.blockSize - 1) / s.blockSize;
    g.blocksY = (height + g.offsetY + s.blockSize - 1) / s.blockSize;
    return g;
}
// The projection's rank tolerance: a column whose part independent of the earlier
// ones is under 1e-5 of its norm counts as dependent. The features are fp32 (relative
// rounding 6e-8, amplified by the per-block scaling), so an exact dependency such as
// a planar wall leaves a residue of about 1e-6 that must not count as a direction.
constexpr double kDependent = 1e-5;

// The integer mix of docs/passes/bmfr.md: xor-shift / multiply by 0x9E3779B9.
uint32_t mix(uint32_t h) {
    h ^= h >> 16;
    h *= 0x9E3779B9u;
    h ^= h >> 13;
    h *= 0x9E3779B9u;
    h ^= h >> 16;
    return h;
}

// Feature values as the GPU makes them: in float (squares saturate at 3e38).
float rawFeature(BmfrFeature f, const BmfrImages& in, uint32_t x, uint32_t y, double u, double v) {
    auto ch = [&](const FloatImage* img, uint32_t c) { return img->at(x, y, c); };
    switch (f) {
    case BmfrFeature::One: return 1.0f;
    case BmfrFeature::NormalX: return ch(in.normal, 0);
    case BmfrFeature::NormalY: return ch(in.normal, 1);
    case BmfrFeature::NormalZ: return ch(in.normal, 2);
    case BmfrFeature::PositionX: return ch(in.position, 0);
    case BmfrFeature::PositionY: return ch(in.position, 1);
    case BmfrFeature::PositionZ: return ch(in.position, 2);
    case BmfrFeature::PositionX2: return std::min(ch(in.position, 0) * ch(in.position, 0), kFloatMax);
    case BmfrFeature::PositionY2: return std::min(ch(in.position, 1) * ch(in.position, 1), kFloatMax);
    case BmfrFeature::PositionZ2: return std::min(ch(in.position, 2) * ch(in.position, 2), kFloatMax);
    case BmfrFeature::AlbedoR: return ch(in.albedo, 0);
    case BmfrFeature::AlbedoG: return ch(in.albedo, 1);
    case BmfrFeature::AlbedoB: return ch(in.albedo, 2);
    case BmfrFeature::Roughness: return ch(in.roughness, 0);
    case BmfrFeature::MeshId: return ch(in.meshId, 0);
    case BmfrFeature::BlockU: return float(u);
    case BmfrFeature::BlockV: return float(v);
    }
    return 0.0f;
}

// One block, ready to fit: noise-free scaled T (rows = valid pixels), noise, z / scale.
struct Block {
    std::vector<uint32_t> px, py;
    std::vector<std::vector<double>> t;       // [feature][row]
    std::vector<std::vector<double>> noise;   // [feature][row]
    std::vector<std::vector<double>> z;       // [channel][row], divided by scale
    double scale[3] = {1, 1, 1};
};

Block gatherBlock(const BmfrImages& in, const passes::BmfrFitSettings& s, const Grid& g,
                  uint32_t bx, uint32_t by, uint32_t frame) {
    Block b;
    const uint32_t w = in.illumination->width, h = in.illumination->height, B = s.blockSize;
    const size_t M = s.features.size();
    std::vector<std::vector<float>> raw(M);
    for (uint32_t ly = 0; ly < B; ++ly) {
        for (uint32_t lx = 0; lx < B; ++lx) {
            const int64_t x = int64_t(bx) * B + lx - g.offsetX, y = int64_t(by) * B + ly - g.offsetY;
            if (x < 0 || y < 0 || x >= int64_t(w) || y >= int64_t(h)) continue;
            b.px.push_back(uint32_t(x));
            b.py.push_back(uint32_t(y));
            const double denom = std::max<double>(B - 1, 1);
            for (size_t m = 0; m < M; ++m)
                raw[m].push_back(rawFeature(s.features[m], in, uint32_t(x), uint32_t(y), lx / denom, ly / denom));
        }
    }
    const size_t W = b.px.size();
    b.t.assign(M, std::vector<double>(W));
    b.noise.assign(M, std::vector<double>(W));
    for (size_t m = 0; m < M; ++m) {
        // Per-block scaling to [-1, 1] (Sec. 3.2); the flat decision is made in float,
        // as the GPU makes it, so both take the same branch.
        float lo = kFloatMax, hi = -kFloatMax;
        for (float f : raw[m]) lo = std::min(lo, f), hi = std::max(hi, f);
        const float halfRange = hi * 0.5f - lo * 0.5f;
        const bool flat = !(2.0f * halfRange > kFlatRange * std::max(std::fabs(lo), std::fabs(hi)));
        for (size_t r = 0; r < W; ++r) {
            double v;
            if (s.features[m] == BmfrFeature::One) v = 1.0;
            else if (flat) v = 0.0;
            else v = std::clamp((0.5 * raw[m][r] - 0.5 * lo) / double(halfRange) - 1.0, -1.0, 1.0);
            b.t[m][r] = v;
            // Flat (all-zero) columns get no noise (docs/passes/bmfr.md, deviations).
            const bool live = s.features[m] == BmfrFeature::One || !flat;
            b.noise[m][r] = live ? bmfrNoise(b.px[r], b.py[r], frame, uint32_t(m), s.epsilon) : 0.0;
        }
    }
    b.z.assign(3, std::vector<double>(W));
    for (uint32_t c = 0; c < 3; ++c) {
        float maxAbs = 0.0f;
        for (size_t r = 0; r < W; ++r) maxAbs = std::max(maxAbs, std::fabs(in.illumination->at(b.px[r], b.py[r], c)));
        b.scale[c] = maxAbs > 0.0f ? double(maxAbs) : 1.0;
        for (size_t r = 0; r < W; ++r) b.z[c][r] = in.illumination->at(b.px[r], b.py[r], c) / b.scale[c];
    }
    return b;
}

// Householder QR of the W x (M + 3) matrix `a` (columns) with the node's column
// dropping: a column whose part independent of the earlier kept columns is at most
// kBmfrDependentColumn of its norm gets alpha = 0 and consumes no row. Then back
// substitution per channel over the kept columns, with the diagonal guard.
std::vector<std::array<double, 3>> solveHouseholder(std::vector<std::vector<double>> a, size_t M) {
    const size_t C = a.size(), W = a.empty() ? 0 : a[0].size();
    std::vector<std::vector<double>> R;   // one row per kept column
    std::vector<size_t> kept;
    size_t rho = 0;                       // next row to reflect onto
    for (size_t k = 0; k < M; ++k) {
        double total = 0.0, norm2 = 0.0;
        for (size_t i = 0; i < W; ++i) total += a[k][i] * a[k][i];
        for (size_t i = rho; i < W; ++i) norm2 += a[k][i] * a[k][i];
        const double norm = std::sqrt(norm2), dep = kDependentColumn;
        if (!(norm > double(kZeroColumn)) || !(norm2 > dep * dep * total)) continue;
        // v = x - alpha e_rho, alpha = -sign(x_rho) |x|; H = I - 2 v v^T / v^T v.
        const double alpha = a[k][rho] >= 0.0 ? -norm : norm;
        std::vector<double> v(W, 0.0);
        for (size_t i = rho; i < W; ++i) v[i] = a[k][i];
        v[rho] -= alpha;
        double vv = 0.0;
        for (size_t i = rho; i < W; ++i) vv += v[i] * v[i];
        std::vector<double> row(C, 0.0);
        row[k] = alpha;
        for (size_t j = k + 1; j < C; ++j) {
            double d = 0.0;
            for (size_t i = rho; i < W; ++i) d += v[i] * a[j][i];
            const double f = 2.0 * d / vv;
            for (size_t i = rho; i < W; ++i) a[j][i] -= f * v[i];
            row[j] = a[j][rho];
        }
        R.push_back(std::move(row));
        kept.push_back(k);
        ++rho;
    }
    double maxDiag = 0.0;
    for (size_t i = 0; i < kept.size(); ++i) maxDiag = std::max(maxDiag, std::fabs(R[i][kept[i]]));
    std::vector<std::array<double, 3>> coef(M, {0.0, 0.0, 0.0});
    for (size_t c = 0; c < 3; ++c) {
        for (size_t ii = 0; ii < kept.size(); ++ii) {
            const size_t i = kept.size() - 1 - ii, k = kept[i];
            double sum = R[i][M + c];
            for (size_t i2 = i + 1; i2 < kept.size(); ++i2) sum -= R[i][kept[i2]] * coef[kept[i2]][c];
            const double d = R[i][k];
            coef[k][c] = (std::fabs(d) > kDiagonalGuard * maxDiag && d != 0.0) ? sum / d : 0.0;
        }
    }
    return coef;
}

FloatImage blankOutput(const BmfrImages& in) {
    FloatImage out(in.illumination->width, in.illumination->height, 4);
    for (uint32_t y = 0; y < out.height; ++y)
        for (uint32_t x = 0; x < out.width; ++x)
            out.at(x, y, 3) = in.illumination->channels >= 4 ? in.illumination->at(x, y, 3) : 1.0f;
    return out;
}

// A block size of 0 follows the frame (passes::bmfrBlockSizeFor, the node's own rule).
void forEachBlock(const BmfrImages& in, const passes::BmfrFitSettings& given, uint64_t frameIndex,
                  const std::function<void(const Block&)>& fn) {
    passes::BmfrFitSettings s = given;
    s.blockSize = passes::bmfrBlockSizeFor({in.illumination->width, in.illumination->height}, given.blockSize);
    const Grid g = blockGrid(in.illumination->width, in.illumination->height, s, frameIndex);
    for (uint32_t by = 0; by < g.blocksY; ++by)
        for (uint32_t bx = 0; bx < g.blocksX; ++bx) fn(gatherBlock(in, s, g, bx, by, uint32_t(frameIndex)));
}

// One channel of a block's prediction, in radiance units. nonNegative (fit.hpp): every
// negative value becomes 0 and the rest are scaled so that the block's sum is kept.
void storeChannel(FloatImage& out, const Block& b, size_t c, std::vector<double> y, bool nonNegative) {
    for (double& v : y) v *= b.scale[c];
    if (nonNegative) {
        double sum = 0.0, positive = 0.0;
        for (const double v : y) {
            sum += v;
            positive += std::max(v, 0.0);
        }
        const double ratio = positive > 0.0 ? std::clamp(sum / positive, 0.0, 1.0) : 0.0;
        for (double& v : y) v = std::max(v, 0.0) * ratio;
    }
    for (size_t r = 0; r < y.size(); ++r) out.at(b.px[r], b.py[r], uint32_t(c)) = float(y[r]);
}

} // namespace

float bmfrNoise(uint32_t x, uint32_t y, uint32_t frame, uint32_t column, float epsilon) {
    const uint32_t h = mix(x ^ mix(y ^ mix(frame ^ mix(column))));
    return epsilon * (float(h >> 8) * (2.0f / 16777216.0f) - 1.0f);
}

FloatImage bmfrFit(const BmfrImages& in, const passes::BmfrFitSettings& s, uint64_t frameIndex) {
    FloatImage out = blankOutput(in);
    const size_t M = s.features.size();
    forEachBlock(in, s, frameIndex, [&](const Block& b) {
        std::vector<std::vector<double>> a(M + 3);
        for (size_t m = 0; m < M; ++m) {
            a[m] = b.t[m];
            for (size_t r = 0; r < a[m].size(); ++r) a[m][r] += b.noise[m][r];
        }
        for (size_t c = 0; c < 3; ++c) a[M + c] = b.z[c];
        const auto coef = solveHouseholder(std::move(a), M);
        for (size_t c = 0; c < 3; ++c) {
            std::vector<double> y(b.px.size(), 0.0);
            for (size_t r = 0; r < y.size(); ++r)
                for (size_t m = 0; m < M; ++m) y[r] += b.t[m][r] * coef[m][c];   // noise-free T (Eq. 6)
            storeChannel(out, b, c, std::move(y), s.nonNegative);
        }
    });
    return out;
}

FloatImage bmfrProjection(const BmfrImages& in, const passes::BmfrFitSettings& s, uint64_t frameIndex) {
    FloatImage out = blankOutput(in);
    forEachBlock(in, s, frameIndex, [&](const Block& b) {
        const size_t W = b.px.size();
        std::vector<std::vector<double>> basis;
        for (const auto& col : b.t) {
            std::vector<double> q = col;
            double original = 0.0;
            for (double v : q) original += v * v;
            original = std::sqrt(original);
            for (int pass = 0; pass < 2; ++pass) {   // twice is enough (Kahan-Parlett)
                for (const auto& e : basis) {
                    double d = 0.0;
                    for (size_t r = 0; r < W; ++r) d += e[r] * q[r];
                    for (size_t r = 0; r < W; ++r) q[r] -= d * e[r];
                }
            }
            double n = 0.0;
            for (double v : q) n += v * v;
            n = std::sqrt(n);
            if (!(n > kDependent * original) || n == 0.0) continue;   // dependent on the earlier columns
            for (double& v : q) v /= n;
            basis.push_back(std::move(q));
        }
        for (size_t c = 0; c < 3; ++c) {
            std::vector<double> y(W, 0.0);
            for (const auto& e : basis) {
                double d = 0.0;
                for (size_t r = 0; r < W; ++r) d += e[r] * b.z[c][r];
                for (size_t r = 0; r < W; ++r) y[r] += d * e[r];
            }
            storeChannel(out, b, c, std::move(y), s.nonNegative);
        }
    });
    return out;
}

} // namespace hush::passes_test::reference
