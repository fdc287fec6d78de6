// passes/common/reproject: the per-pixel reprojection decision against the CPU
// reference, and the cases SVGF Sec. 4.1 names: static camera, sub-pixel motion,
// a moving object (mesh id change), disocclusions the 3x3 fallback does and does not
// recover, out-of-screen motion, extreme values, tiny sizes, invalid history.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <functional>

#include <hush/passes/common/reproject.hpp>
#include <hush/passes/common/surface.hpp>

#include "reference/common_reproject.hpp"
#include "reference/common_surface.hpp"

using namespace hush;
using namespace hush::passes_test;
using passes::ReprojectionMode;

namespace {

// One pixel of a packed surface (common/surface.hpp layout).
struct SurfacePoint {
    float nx = 0, ny = 0, nz = 1, depth = 1, gx = 0, gy = 0, mesh = 0;
};
using SurfaceFn = std::function<SurfacePoint(uint32_t x, uint32_t y)>;

reference::SurfaceImages makeSurface(uint32_t w, uint32_t h, const SurfaceFn& f) {
    reference::SurfaceImages s{FloatImage(w, h, 4), FloatImage(w, h, 4)};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const SurfacePoint p = f(x, y);
            const float n[4] = {p.nx, p.ny, p.nz, p.depth}, g[4] = {p.gx, p.gy, p.mesh, 0.0f};
            for (uint32_t c = 0; c < 4; ++c) s.normalDepth.at(x, y, c) = n[c], s.gradientMesh.at(x, y, c) = g[c];
        }
    return s;
}

FloatImage constantMotion(uint32_t w, uint32_t h, float mx, float my) {
    return makeImage(w, h, 2, [&](uint32_t, uint32_t, uint32_t c) { return c == 0 ? mx : my; });
}

uint32_t modeAt(const FloatImage& d, uint32_t x, uint32_t y) { return uint32_t(d.at(x, y, 3)); }
uint32_t maskAt(const FloatImage& d, uint32_t x, uint32_t y) { return uint32_t(d.at(x, y, 2)); }

// Runs the node on imported surfaces for two frames: the first (history invalid)
// must be all disoccluded; returns the second.
FloatImage runReproject(const FloatImage& motion, const reference::SurfaceImages& cur,
                        const reference::SurfaceImages& prev, const passes::ReprojectSettings& s = {}) {
    NodeHarness t({motion.width, motion.height});
    auto mv = t.input("motion", motion, rhi::Format::RG32Float);
    const passes::Surface current{t.input("cur.nd", cur.normalDepth), t.input("cur.gm", cur.gradientMesh)};
    const passes::Surface previous{t.input("prev.nd", prev.normalDepth), t.input("prev.gm", prev.gradientMesh)};
    auto decision = passes::addReprojectPass(t.ctx, "reproject", mv, current, previous, s);
    const auto first = t.runOnce(decision);
    HUSH_REQUIRE_IMAGES_MATCH(first, reference::reproject(motion, cur, prev, s, false), 1e-5f, 1e-6f);
    for (uint32_t y = 0; y < first.height; ++y)
        for (uint32_t x = 0; x < first.width; ++x) REQUIRE(modeAt(first, x, y) == 0);
    t.graph.execute();
    t.graph.waitIdle();
    return readOutput(t.graph, decision);
}

// Positions exact to fp32 rounding; masks and modes (integers) exactly.
void requireMatchesReference(const FloatImage& gpu, const FloatImage& motion, const reference::SurfaceImages& cur,
                             const reference::SurfaceImages& prev, const passes::ReprojectSettings& s = {}) {
    REQUIRE(nonFiniteCount(gpu) == 0);
    HUSH_REQUIRE_IMAGES_MATCH(gpu, reference::reproject(motion, cur, prev, s, true), 1e-5f, 1e-6f);
}

} // namespace

TEST_CASE("reproject: a static camera keeps every surface pixel's own texel", "[reproject]") {
    test::ValidationScope scope;
    const uint32_t w = 19, h = 13;
    auto noise = randomImage(w, h, 3, -0.1f, 0.1f, 7);
    auto surface = makeSurface(w, h, [&](uint32_t x, uint32_t y) {
        SurfacePoint p;
        const float n[3] = {noise.at(x, y, 0), noise.at(x, y, 1), 1.0f};
        const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        p.nx = n[0] / len, p.ny = n[1] / len, p.nz = n[2] / len;
        p.depth = 3.0f + 0.1f * float(x) - 0.07f * float(y);
        p.gx = 0.1f, p.gy = -0.07f;
        p.mesh = x < 6 ? -1.0f : float(1 + (x + y) % 3);   // background on the left
        return p;
    });
    auto motion = constantMotion(w, h, 0.0f, 0.0f);
    auto gpu = runReproject(motion, surface, surface);
    requireMatchesReference(gpu, motion, surface, surface);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            INFO(x << ", " << y);
            if (x < 6) {
                REQUIRE(modeAt(gpu, x, y) == 0);   // background never reprojects
            } else {
                REQUIRE(modeAt(gpu, x, y) == 1);
                REQUIRE(maskAt(gpu, x, y) == 1);   // only the own texel has weight
                REQUIRE(gpu.at(x, y, 0) == float(x));
                REQUIRE(gpu.at(x, y, 1) == float(y));
            }
        }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("reproject: sub-pixel translation of a tilted plane keeps all four bilinear taps", "[reproject]") {
    test::ValidationScope scope;
    const uint32_t w = 23, h = 17;
    const float mx = 0.3f, my = -0.6f, gx = 0.2f, gy = 0.05f;
    // Current pixel p shows what the previous frame showed at p + motion.
    auto plane = [&](float x, float y) { return 4.0f + gx * x + gy * y; };
    auto at = [&](float x, float y) {
        SurfacePoint p;
        p.depth = plane(x, y), p.gx = gx, p.gy = gy, p.mesh = 5;
        return p;
    };
    auto cur = makeSurface(w, h, [&](uint32_t x, uint32_t y) { return at(float(x), float(y)); });
    auto prev = makeSurface(w, h, [&](uint32_t x, uint32_t y) { return at(float(x) - mx, float(y) - my); });
    auto motion = constantMotion(w, h, mx, my);
    auto gpu = runReproject(motion, cur, prev);
    requireMatchesReference(gpu, motion, cur, prev);
    for (uint32_t y = 1; y + 1 < h; ++y)
        for (uint32_t x = 0; x + 1 < w; ++x) {
            INFO(x << ", " << y);
            REQUIRE(modeAt(gpu, x, y) == 1);
            REQUIRE(maskAt(gpu, x, y) == 15);
            // The renormalised bilinear fetch of the previous depth is the plane at p.
            std::array<float, 4> v{};
            REQUIRE(reference::fetchReprojected(prev.normalDepth, gpu, x, y, v));
            REQUIRE(v[3] == Approx(cur.normalDepth.at(x, y, 3)).epsilon(1e-5));
        }
    // Top row: the upper taps are above the image; the lower two carry all the weight.
    REQUIRE(maskAt(gpu, 5, 0) == 12);
    // Right column: the right taps are beyond the edge.
    REQUIRE(maskAt(gpu, w - 1, 5) == 5);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("reproject: a moving object's mesh id rejects taps, the 3x3 fallback recovers a one-pixel "
          "disocclusion and not a two-pixel one",
          "[reproject]") {
    test::ValidationScope scope;
    const uint32_t w = 24, h = 12;
    // A box (mesh 2, depth 2) over a wall (mesh 1, depth 5) moves 2 pixels right:
    // last frame it covered x in [6, 12), now [8, 14); rows 3..8.
    auto scene = [&](int boxLeft) {
        return makeSurface(w, h, [=](uint32_t x, uint32_t y) {
            SurfacePoint p;
            const bool box = int(x) >= boxLeft && int(x) < boxLeft + 6 && y >= 3 && y <= 8;
            p.depth = box ? 2.0f : 5.0f;
            p.mesh = box ? 2.0f : 1.0f;
            return p;
        });
    };
    auto prev = scene(6), cur = scene(8);
    auto motion = makeImage(w, h, 2, [&](uint32_t x, uint32_t y, uint32_t c) {
        const bool box = x >= 8 && x < 14 && y >= 3 && y <= 8;
        return c == 0 && box ? -2.0f : 0.0f;
    });
    auto gpu = runReproject(motion, cur, prev);
    requireMatchesReference(gpu, motion, cur, prev);
    // The box follows itself.
    for (uint32_t x = 8; x < 14; ++x) REQUIRE(modeAt(gpu, x, 5) == 1);
    // Revealed wall at x = 6: last frame's box covered it, its left neighbour was wall.
    REQUIRE(modeAt(gpu, 6, 5) == 2);
    REQUIRE(maskAt(gpu, 6, 5) == (1u | 8u | 64u));   // the left column of the 3x3
    REQUIRE(gpu.at(6, 5, 0) == 5.0f);
    // At x = 7 the whole 3x3 (x 6..8) was box: a true disocclusion.
    REQUIRE(modeAt(gpu, 7, 5) == 0);
    // Without the fallback, x = 6 is disoccluded too.
    auto noFallback = runReproject(motion, cur, prev, {.fallback3x3 = false});
    requireMatchesReference(noFallback, motion, cur, prev, {.fallback3x3 = false});
    REQUIRE(modeAt(noFallback, 6, 5) == 0);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("reproject: normal and depth tests each reject a tap on the same mesh", "[reproject]") {
    test::ValidationScope scope;
    const uint32_t w = 16, h = 8;
    auto cur = makeSurface(w, h, [](uint32_t, uint32_t) { return SurfacePoint{.depth = 10.0f, .mesh = 3}; });
    // Column 4: normal turned by 30 degrees (cos 0.866 < 0.9); column 8: 25 degrees
    // (cos 0.906, kept); column 11: depth 3 % off (beyond 2 %); column 13: 1 % (kept).
    auto prev = makeSurface(w, h, [](uint32_t x, uint32_t) {
        SurfacePoint p{.depth = 10.0f, .mesh = 3};
        const float deg = x == 4 ? 30.0f : x == 8 ? 25.0f : 0.0f;
        p.nx = std::sin(deg * 3.14159265f / 180.0f), p.nz = std::cos(deg * 3.14159265f / 180.0f);
        p.depth = x == 11 ? 10.3f : x == 13 ? 10.1f : 10.0f;
        return p;
    });
    auto motion = constantMotion(w, h, 0.0f, 0.0f);
    auto gpu = runReproject(motion, cur, prev);
    requireMatchesReference(gpu, motion, cur, prev);
    // Rejected own texel, so the 3x3 fallback takes the neighbours (both sides).
    REQUIRE(modeAt(gpu, 4, 3) == 2);
    REQUIRE(maskAt(gpu, 4, 3) == 0x1FFu - (1u << 1) - (1u << 4) - (1u << 7));
    REQUIRE(modeAt(gpu, 8, 3) == 1);
    REQUIRE(modeAt(gpu, 11, 3) == 2);
    REQUIRE(modeAt(gpu, 13, 3) == 1);
    // A stricter normal cone drops column 8 too.
    auto strict = runReproject(motion, cur, prev, {.normalCosine = 0.95f});
    requireMatchesReference(strict, motion, cur, prev, {.normalCosine = 0.95f});
    REQUIRE(modeAt(strict, 8, 3) == 2);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("reproject: motion out of the screen is a disocclusion, and huge motion is NaN-free", "[reproject]") {
    test::ValidationScope scope;
    const uint32_t w = 12, h = 7;
    auto surface = makeSurface(w, h, [](uint32_t, uint32_t) { return SurfacePoint{.depth = 2.0f, .mesh = 0}; });
    for (float m : {-5.0f, 9.5f, 1e30f, -1e30f, 65504.0f, -3.0e38f}) {
        INFO("motion " << m);
        auto motion = constantMotion(w, h, m, 0.5f * m);
        auto gpu = runReproject(motion, surface, surface);
        requireMatchesReference(gpu, motion, surface, surface);
        if (std::fabs(m) > 100.0f) {
            for (uint32_t y = 0; y < h; ++y)
                for (uint32_t x = 0; x < w; ++x) REQUIRE(modeAt(gpu, x, y) == 0);
        }
    }
    // Motion -5 in x: columns 0..3 look left of the image; column 4's 3x3 reaches column 0.
    auto motion = constantMotion(w, h, -5.0f, 0.0f);
    auto gpu = runReproject(motion, surface, surface);
    for (uint32_t x = 0; x < 4; ++x) REQUIRE(modeAt(gpu, x, 3) == 0);
    REQUIRE(modeAt(gpu, 4, 3) == 2);
    REQUIRE(modeAt(gpu, 5, 3) == 1);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("reproject: extreme depths and gradients, 1x1 and 3x5, stay finite and match", "[reproject]") {
    test::ValidationScope scope;
    for (auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{3, 5}, rhi::Extent2D{9, 6}}) {
        for (float v : {0.0f, 1e-30f, 65504.0f, 1e6f, 3.0e38f}) {
            INFO(size.width << "x" << size.height << " value " << v);
            auto cur = makeSurface(size.width, size.height, [&](uint32_t x, uint32_t y) {
                return SurfacePoint{.nx = 0, .ny = 0, .nz = v == 0.0f ? 0.0f : 1.0f, .depth = v * float(1 + x % 2),
                                    .gx = v, .gy = -v, .mesh = float(y % 2)};
            });
            auto prev = makeSurface(size.width, size.height, [&](uint32_t x, uint32_t) {
                return SurfacePoint{.depth = v * float(1 + x % 3), .gx = v, .gy = v, .mesh = 1.0f};
            });
            auto motion = constantMotion(size.width, size.height, 0.25f, -0.75f);
            auto gpu = runReproject(motion, cur, prev);
            requireMatchesReference(gpu, motion, cur, prev);
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("reproject: resetHistory makes the next frame disoccluded everywhere", "[reproject]") {
    test::ValidationScope scope;
    const uint32_t w = 8, h = 8;
    auto surface = makeSurface(w, h, [](uint32_t, uint32_t) { return SurfacePoint{.depth = 1.0f, .mesh = 0}; });
    NodeHarness t({w, h});
    auto mv = t.input("motion", constantMotion(w, h, 0, 0), rhi::Format::RG32Float);
    const passes::Surface s{t.input("nd", surface.normalDepth), t.input("gm", surface.gradientMesh)};
    auto decision = passes::addReprojectPass(t.ctx, "reproject", mv, s, s);
    auto modes = [&] {
        t.graph.execute();
        t.graph.waitIdle();
        auto d = readOutput(t.graph, decision);
        uint32_t sum = 0;
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) sum += modeAt(d, x, y);
        return sum;
    };
    t.graph.markOutput(decision);
    REQUIRE(modes() == 0);
    REQUIRE(modes() == w * h);
    t.graph.resetHistory();
    REQUIRE(modes() == 0);
    REQUIRE(modes() == w * h);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("reproject reads last frame's surface through surfaceHistory, frame after frame", "[reproject]") {
    test::ValidationScope scope;
    const uint32_t w = 13, h = 9;
    auto normal = makeImage(w, h, 3, [](uint32_t, uint32_t, uint32_t c) { return c == 2 ? 1.0f : 0.0f; });
    auto depth = makeImage(w, h, 1, [](uint32_t x, uint32_t y, uint32_t) { return 1.0f + 0.1f * float(x + y); });
    auto mesh = makeImage(w, h, 1, [](uint32_t x, uint32_t, uint32_t) { return x == 0 ? -1.0f : 4.0f; });
    NodeHarness t({w, h});
    auto current = passes::addSurfacePass(t.ctx, "surface", t.input("normal", normal),
                                          t.input("depth", depth, rhi::Format::R32Float),
                                          t.input("meshid", mesh, rhi::Format::R32Float));
    auto previous = passes::surfaceHistory(t.ctx, current);
    auto mv = t.input("motion", constantMotion(w, h, 0.0f, 0.0f), rhi::Format::RG32Float);
    auto decision = passes::addReprojectPass(t.ctx, "reproject", mv, current, previous);
    t.graph.markOutput(decision);
    for (uint32_t f = 0; f < 3; ++f) {
        INFO("frame " << f);
        t.graph.execute();
        t.graph.waitIdle();
        auto d = readOutput(t.graph, decision);
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                const bool kept = f > 0 && x > 0;
                REQUIRE(modeAt(d, x, y) == (kept ? 1u : 0u));
                if (kept) REQUIRE(maskAt(d, x, y) == 1u);
            }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
