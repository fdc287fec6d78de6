// svgf/temporal_accumulation (Schied et al. 2017 Sec. 4.1): against the CPU
// reference over several frames, through every kind of reprojection decision; the
// cumulative average of the first frames, the history length counter, its resets;
// the chain reproject -> accumulate; extreme values and tiny sizes.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include <hush/passes/common/reproject.hpp>
#include <hush/passes/svgf/temporal_accumulation.hpp>

#include "reference/common_reproject.hpp"
#include "reference/common_surface.hpp"
#include "reference/svgf_temporal_accumulation.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

// The temporal node on an imported illumination and decision; its colour history is
// its own output (colorHistoryName = its name), as the tests need no a-trous.
struct TemporalRig {
    NodeHarness t;
    passes::SvgfTemporal out;

    TemporalRig(uint32_t w, uint32_t h, const passes::SvgfTemporalSettings& s = {}) : t({w, h}) {
        auto illumination = t.input("illumination", FloatImage(w, h, 4));
        auto decision = t.input("decision", FloatImage(w, h, 4));
        out = passes::addSvgfTemporalPass(t.ctx, "temporal", illumination, decision, {}, s);
        t.graph.markOutput(out.color);
        t.graph.markOutput(out.moments);
    }
    reference::SvgfTemporalImages frame(const FloatImage& illumination, const FloatImage& decision) {
        t.update("illumination", illumination);
        t.update("decision", decision);
        t.graph.execute();
        t.graph.waitIdle();
        return {readOutput(t.graph, out.color), readOutput(t.graph, out.moments)};
    }
};

// Decisions of every mode, footprints inside the image, random fractions and masks
// (some that the reprojection pass never makes, which consumers must still survive).
FloatImage randomDecisions(uint32_t w, uint32_t h, uint64_t seed) {
    test::Lcg lcg(seed);
    FloatImage d(w, h, 4);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            uint32_t mode = lcg.next() % 3;
            if (mode == 1 && (w < 2 || h < 2)) mode = 0;
            if (mode == 2 && (w < 3 || h < 3)) mode = 0;
            float px = lcg.uniform(-2.0f, float(w) + 1.0f), py = lcg.uniform(-2.0f, float(h) + 1.0f);
            uint32_t mask = 0;
            if (mode == 1) {
                px = float(lcg.next() % (w - 1)) + lcg.uniform(0.01f, 0.99f);
                py = float(lcg.next() % (h - 1)) + lcg.uniform(0.01f, 0.99f);
                mask = 1 + lcg.next() % 15;
                // Some on a texel column: the right taps weigh 0, and a mask of only
                // those (2, 8, 10) must fall back to equal weights, not 0/0.
                if (lcg.next() % 4 == 0) px = std::floor(px);
            } else if (mode == 2) {
                px = float(lcg.next() % (w - 2));
                py = float(lcg.next() % (h - 2));
                mask = 1 + lcg.next() % 511;
            }
            d.at(x, y, 0) = px, d.at(x, y, 1) = py, d.at(x, y, 2) = float(mask), d.at(x, y, 3) = float(mode);
        }
    return d;
}

// GPU and CPU evaluate a * c + (1 - a) * prev in fp32 (maybe fused): a few ulps a frame.
void requireTemporalMatch(const reference::SvgfTemporalImages& gpu, const reference::SvgfTemporalImages& ref) {
    REQUIRE(nonFiniteCount(gpu.color) == 0);
    REQUIRE(nonFiniteCount(gpu.moments) == 0);
    HUSH_REQUIRE_IMAGES_MATCH(gpu.color, ref.color, 1e-6f, 1e-5f);
    HUSH_REQUIRE_IMAGES_MATCH(gpu.moments, ref.moments, 1e-6f, 1e-5f);
}

} // namespace

TEST_CASE("svgf temporal matches the CPU reference over frames through bilinear, 3x3 and disoccluded decisions",
          "[svgf-temporal]") {
    test::ValidationScope scope;
    const uint32_t w = 17, h = 11;
    TemporalRig rig(w, h);
    reference::SvgfTemporalImages ref;
    for (uint32_t f = 0; f < 6; ++f) {
        INFO("frame " << f);
        auto illumination = randomImage(w, h, 4, 0.0f, 4.0f, 100 + f);
        auto decision = randomDecisions(w, h, 200 + f);
        auto gpu = rig.frame(illumination, decision);
        ref = reference::svgfTemporal(illumination, decision, ref, {}, f > 0);
        requireTemporalMatch(gpu, ref);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("svgf temporal: cumulative average first, then alpha 0.2, and history length counts, caps and resets",
          "[svgf-temporal]") {
    test::ValidationScope scope;
    const uint32_t w = 4, h = 3;
    const auto still = reference::identityDecision(w, h);
    TemporalRig rig(w, h, {.maxHistoryLength = 8.0f});
    auto grey = [&](float v) { return FloatImage(w, h, 4, v); };
    // Samples 1, 2, ..., 5: the first five outputs are their running means.
    double sum = 0.0;
    for (uint32_t n = 1; n <= 5; ++n) {
        auto out = rig.frame(grey(float(n)), still);
        sum += n;
        INFO("frame " << n);
        REQUIRE(out.moments.at(1, 1, 2) == float(n));
        REQUIRE(out.color.at(1, 1, 0) == Approx(sum / n).epsilon(1e-6));
        REQUIRE(out.moments.at(1, 1, 0) == Approx(sum / n).epsilon(1e-6));   // luminance of grey = grey
    }
    // Then the exponential average with 0.2: 0.2 * 10 + 0.8 * 3.
    auto out = rig.frame(grey(10.0f), still);
    REQUIRE(out.color.at(2, 0, 1) == Approx(0.2 * 10.0 + 0.8 * 3.0).epsilon(1e-6));
    REQUIRE(out.moments.at(2, 0, 2) == 6.0f);
    for (int i = 0; i < 4; ++i) out = rig.frame(grey(10.0f), still);
    REQUIRE(out.moments.at(2, 0, 2) == 8.0f);   // capped
    // A disocclusion at (3, 2) resets that pixel alone.
    auto partly = still;
    partly.at(3, 2, 3) = 0.0f;
    out = rig.frame(grey(7.0f), partly);
    REQUIRE(out.moments.at(3, 2, 2) == 1.0f);
    REQUIRE(out.color.at(3, 2, 0) == 7.0f);
    REQUIRE(out.moments.at(0, 0, 2) == 8.0f);
    // A history reset (camera cut) resets every pixel for one frame.
    rig.t.graph.resetHistory();
    out = rig.frame(grey(3.0f), still);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            REQUIRE(out.moments.at(x, y, 2) == 1.0f);
            REQUIRE(out.color.at(x, y, 2) == 3.0f);
            REQUIRE(out.moments.at(x, y, 1) == 9.0f);
        }
    out = rig.frame(grey(5.0f), still);
    REQUIRE(out.moments.at(1, 2, 2) == 2.0f);
    REQUIRE(out.color.at(1, 2, 0) == Approx(4.0));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("svgf temporal after reproject follows a translating surface like the CPU chain", "[svgf-temporal]") {
    test::ValidationScope scope;
    const uint32_t w = 21, h = 14;
    const float mx = -0.35f, my = 0.8f;
    // A tilted plane (mesh 1) moving with the motion, a static background strip (-1).
    auto surfaceAt = [&](float x, float y, bool background) {
        const float z = 3.0f + 0.1f * x + 0.02f * y;
        return std::array<float, 8>{0, 0, 1, z, 0.1f, 0.02f, background ? -1.0f : 1.0f, 0};
    };
    auto makeSurface = [&](float ox, float oy) {
        reference::SurfaceImages s{FloatImage(w, h, 4), FloatImage(w, h, 4)};
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                auto v = surfaceAt(float(x) + ox, float(y) + oy, y < 2);
                for (uint32_t c = 0; c < 4; ++c) {
                    s.normalDepth.at(x, y, c) = v[c];
                    s.gradientMesh.at(x, y, c) = v[4 + c];
                }
            }
        return s;
    };
    auto cur = makeSurface(0, 0), prev = makeSurface(-mx, -my);
    auto motion = makeImage(w, h, 2, [&](uint32_t, uint32_t, uint32_t c) { return c == 0 ? mx : my; });

    NodeHarness t({w, h});
    auto mv = t.input("motion", motion, rhi::Format::RG32Float);
    auto illum = t.input("illumination", FloatImage(w, h, 4));
    const passes::Surface current{t.input("cur.nd", cur.normalDepth), t.input("cur.gm", cur.gradientMesh)};
    const passes::Surface previous{t.input("prev.nd", prev.normalDepth), t.input("prev.gm", prev.gradientMesh)};
    auto decision = passes::addReprojectPass(t.ctx, "reproject", mv, current, previous);
    auto temporal = passes::addSvgfTemporalPass(t.ctx, "temporal", illum, decision);
    t.graph.markOutput(temporal.color);
    t.graph.markOutput(temporal.moments);
    reference::SvgfTemporalImages ref;
    for (uint32_t f = 0; f < 5; ++f) {
        INFO("frame " << f);
        auto illumination = randomImage(w, h, 4, 0.0f, 2.0f, 300 + f);
        t.update("illumination", illumination);
        t.graph.execute();
        t.graph.waitIdle();
        reference::SvgfTemporalImages gpu{readOutput(t.graph, temporal.color), readOutput(t.graph, temporal.moments)};
        auto refDecision = reference::reproject(motion, cur, prev, {}, f > 0);
        ref = reference::svgfTemporal(illumination, refDecision, ref, {}, f > 0);
        requireTemporalMatch(gpu, ref);
        // Interior plane pixels have accumulated every frame; the background never.
        REQUIRE(gpu.moments.at(10, 7, 2) == float(f + 1));
        REQUIRE(gpu.moments.at(10, 0, 2) == 1.0f);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("svgf temporal: zero, 1e-30, 65504 and 1e6 fireflies stay finite on 1x1, 3x5 and 16x9", "[svgf-temporal]") {
    test::ValidationScope scope;
    for (auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{3, 5}, rhi::Extent2D{16, 9}}) {
        for (float v : {0.0f, 1e-30f, 65504.0f, 1e6f, 1e8f}) {
            INFO(size.width << "x" << size.height << " value " << v);
            const uint32_t w = size.width, h = size.height;
            TemporalRig rig(w, h);
            reference::SvgfTemporalImages ref;
            for (uint32_t f = 0; f < 4; ++f) {
                // Sparse fireflies of value v over a dim background (or v everywhere on odd frames).
                auto illumination = makeImage(w, h, 4, [&](uint32_t x, uint32_t y, uint32_t) {
                    return (f % 2 == 1 || (x * 7 + y * 3 + f) % 5 == 0) ? v : 0.01f;
                });
                auto decision = randomDecisions(w, h, 400 + f);
                auto gpu = rig.frame(illumination, decision);
                ref = reference::svgfTemporal(illumination, decision, ref, {}, f > 0);
                requireTemporalMatch(gpu, ref);
            }
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
