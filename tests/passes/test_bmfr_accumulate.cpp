// bmfr/accumulate (Koskela et al. 2019 Sec. 3.1 and 3.3): against the CPU reference
// over frames through every kind of reprojection decision, for both stages' weights;
// the cumulative average first, then the exponential one; the sample count, its
// saturation, its bilinear rounding and its restart on a disocclusion and a reset;
// the post-accumulation reusing the first stage's decision; extremes and tiny sizes.
#include <catch2/catch.hpp>

#include <cmath>

#include <hush/passes/bmfr/accumulate.hpp>
#include <hush/core/error.hpp>

#include "reference/bmfr_accumulate.hpp"
#include "reference/common_reproject.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

// One accumulate node (or the two stages on one decision) on imported textures.
struct AccumulateRig {
    NodeHarness t;
    TextureHandle first, second;

    AccumulateRig(uint32_t w, uint32_t h, const passes::BmfrAccumulateSettings& s, bool twoStages = false)
        : t({w, h}) {
        auto input = t.input("input", FloatImage(w, h, 4));
        auto decision = t.input("decision", FloatImage(w, h, 4));
        first = passes::addBmfrAccumulatePass(t.ctx, "acc", input, decision, s);
        t.graph.markOutput(first);
        if (twoStages) {
            second = passes::addBmfrAccumulatePass(t.ctx, "post", first, decision, passes::bmfrPostAccumulateSettings());
            t.graph.markOutput(second);
        }
    }
    FloatImage frame(const FloatImage& input, const FloatImage& decision) {
        t.update("input", input);
        t.update("decision", decision);
        t.graph.execute();
        t.graph.waitIdle();
        return readOutput(t.graph, first);
    }
};

// Decisions of every mode with random fractions and masks, footprints inside the image.
FloatImage randomDecisions(uint32_t w, uint32_t h, uint64_t seed) {
    test::Lcg lcg(seed);
    FloatImage d(w, h, 4);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            uint32_t mode = lcg.next() % 4;   // 3 counts as a second chance of bilinear
            if (mode == 3) mode = 1;
            if (mode == 1 && (w < 2 || h < 2)) mode = 0;
            if (mode == 2 && (w < 3 || h < 3)) mode = 0;
            float px = 0.0f, py = 0.0f;
            uint32_t mask = 0;
            if (mode == 1) {
                px = float(lcg.next() % (w - 1)) + lcg.uniform(0.01f, 0.99f);
                py = float(lcg.next() % (h - 1)) + lcg.uniform(0.01f, 0.99f);
                mask = 1 + lcg.next() % 15;
            } else if (mode == 2) {
                px = float(lcg.next() % (w - 2));
                py = float(lcg.next() % (h - 2));
                mask = 1 + lcg.next() % 511;
            }
            d.at(x, y, 0) = px, d.at(x, y, 1) = py, d.at(x, y, 2) = float(mask), d.at(x, y, 3) = float(mode);
        }
    return d;
}

// GPU and CPU both blend in fp32 (the GPU maybe fused): a few ulps a frame. The count
// is an exact small integer on both sides.
void requireAccumulateMatch(const FloatImage& gpu, const FloatImage& ref) {
    REQUIRE(nonFiniteCount(gpu) == 0);
    HUSH_REQUIRE_IMAGES_MATCH(gpu, ref, 1e-6f, 1e-5f);
}

} // namespace

TEST_CASE("bmfr accumulate matches the CPU reference through bilinear, 3x3 and disoccluded decisions",
          "[bmfr][bmfr-accumulate]") {
    test::ValidationScope scope;
    const uint32_t w = 19, h = 13;
    for (float minWeight : {0.2f, 0.1f, 0.3f, 1.0f}) {
        INFO("minWeight " << minWeight);
        const passes::BmfrAccumulateSettings s{.minWeight = minWeight};
        AccumulateRig rig(w, h, s);
        FloatImage ref;
        for (uint32_t f = 0; f < 12; ++f) {
            INFO("frame " << f);
            auto input = randomImage(w, h, 4, 0.0f, 4.0f, 500 + f);
            // Mostly the identity (long histories), random decisions on some frames.
            auto decision = f % 3 == 2 ? randomDecisions(w, h, 600 + f) : reference::identityDecision(w, h);
            auto gpu = rig.frame(input, decision);
            ref = reference::bmfrAccumulate(input, decision, ref, s, f > 0);
            requireAccumulateMatch(gpu, ref);
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("bmfr accumulate: cumulative average until the weight reaches 20 %, then exponential, and the count "
          "saturates and restarts",
          "[bmfr][bmfr-accumulate]") {
    test::ValidationScope scope;
    const uint32_t w = 4, h = 3;
    const auto still = reference::identityDecision(w, h);
    auto grey = [&](float v) { return FloatImage(w, h, 4, v); };
    REQUIRE(passes::bmfrAccumulateCountCap({}) == 5);
    REQUIRE(passes::bmfrAccumulateCountCap(passes::bmfrPostAccumulateSettings()) == 10);
    AccumulateRig rig(w, h, {});
    // Samples 1..5: the running mean (weights 1, 1/2, 1/3, 1/4, 1/5 >= 0.2).
    double sum = 0.0;
    for (uint32_t n = 1; n <= 5; ++n) {
        INFO("sample " << n);
        auto out = rig.frame(grey(float(n)), still);
        sum += n;
        REQUIRE(out.at(1, 1, 3) == float(n));
        REQUIRE(out.at(1, 1, 0) == Approx(sum / n).epsilon(1e-6));
    }
    // Then 0.2 * new + 0.8 * old, and the count stays at 5.
    auto out = rig.frame(grey(10.0f), still);
    REQUIRE(out.at(2, 0, 1) == Approx(0.2 * 10.0 + 0.8 * 3.0).epsilon(1e-6));
    REQUIRE(out.at(2, 0, 3) == 5.0f);
    // A disocclusion at (3, 2) restarts that pixel alone: the sample, count 1; then the
    // plain mean of the two samples since.
    auto partly = still;
    partly.at(3, 2, 3) = 0.0f;
    out = rig.frame(grey(7.0f), partly);
    REQUIRE(out.at(3, 2, 3) == 1.0f);
    REQUIRE(out.at(3, 2, 0) == 7.0f);
    REQUIRE(out.at(0, 0, 3) == 5.0f);
    out = rig.frame(grey(1.0f), still);
    REQUIRE(out.at(3, 2, 3) == 2.0f);
    REQUIRE(out.at(3, 2, 0) == Approx(4.0).epsilon(1e-6));
    // A history reset restarts every pixel.
    rig.t.graph.resetHistory();
    out = rig.frame(grey(3.0f), still);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            REQUIRE(out.at(x, y, 3) == 1.0f);
            REQUIRE(out.at(x, y, 2) == 3.0f);
        }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("bmfr accumulate: the post stage's 10 % and the bilinear count rounded to an integer",
          "[bmfr][bmfr-accumulate]") {
    test::ValidationScope scope;
    const uint32_t w = 4, h = 2;
    const auto still = reference::identityDecision(w, h);
    AccumulateRig rig(w, h, passes::bmfrPostAccumulateSettings());
    // Ten samples of 1..10 are a plain mean (weights down to 1/10), the 11th blends by 0.1.
    FloatImage out;
    for (uint32_t n = 1; n <= 10; ++n) out = rig.frame(FloatImage(w, h, 4, float(n)), still);
    REQUIRE(out.at(0, 0, 3) == 10.0f);
    REQUIRE(out.at(0, 0, 0) == Approx(5.5).epsilon(1e-6));
    // Column 1 restarts (count 1, value 0) while column 0 keeps count 10, value 0.1 * 0 + 0.9 * 5.5.
    auto split = still;
    for (uint32_t y = 0; y < h; ++y) split.at(1, y, 3) = 0.0f;
    out = rig.frame(FloatImage(w, h, 4, 0.0f), split);
    REQUIRE(out.at(0, 0, 3) == 10.0f);
    REQUIRE(out.at(1, 0, 3) == 1.0f);
    REQUIRE(out.at(0, 0, 0) == Approx(0.9 * 5.5).epsilon(1e-6));
    // Pixel (0, 0) now reads the 2x2 footprint at (0.25, 0) of columns 0 and 1, row 0 only
    // (mask 0b0011): weights 0.75 / 0.25, count 0.75 * 10 + 0.25 * 1 = 7.75 -> 8, so n = 9
    // and the sample's weight is 1/9 (still the cumulative average).
    auto bilinear = still;
    bilinear.at(0, 0, 0) = 0.25f;
    bilinear.at(0, 0, 2) = 3.0f;
    const double history = 0.75 * (0.9 * 5.5) + 0.25 * 0.0;
    out = rig.frame(FloatImage(w, h, 4, 9.0f), bilinear);
    REQUIRE(out.at(0, 0, 3) == 9.0f);
    REQUIRE(out.at(0, 0, 0) == Approx(9.0 / 9.0 + (8.0 / 9.0) * history).epsilon(1e-5));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("bmfr post-accumulation reuses the first stage's decision: both restart on the same pixels",
          "[bmfr][bmfr-accumulate]") {
    test::ValidationScope scope;
    const uint32_t w = 15, h = 9;
    AccumulateRig rig(w, h, {}, /*twoStages=*/true);
    FloatImage refFirst, refSecond;
    for (uint32_t f = 0; f < 8; ++f) {
        INFO("frame " << f);
        auto input = randomImage(w, h, 4, 0.0f, 2.0f, 700 + f);
        auto decision = f % 2 == 1 ? randomDecisions(w, h, 800 + f) : reference::identityDecision(w, h);
        const auto first = rig.frame(input, decision);
        const auto second = readOutput(rig.t.graph, rig.second);
        refFirst = reference::bmfrAccumulate(input, decision, refFirst, {}, f > 0);
        refSecond = reference::bmfrAccumulate(refFirst, decision, refSecond, passes::bmfrPostAccumulateSettings(), f > 0);
        requireAccumulateMatch(first, refFirst);
        requireAccumulateMatch(second, refSecond);
        // Wherever the decision says disoccluded, both stages restart there.
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                if (decision.at(x, y, 3) == 0.0f) {
                    REQUIRE(first.at(x, y, 3) == 1.0f);
                    REQUIRE(second.at(x, y, 3) == 1.0f);
                    REQUIRE(second.at(x, y, 0) == first.at(x, y, 0));
                }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("bmfr accumulate: zero, 1e-30, 65504, 1e6 and 1e12 stay finite on 1x1, 3x5 and 16x9",
          "[bmfr][bmfr-accumulate]") {
    test::ValidationScope scope;
    for (auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{3, 5}, rhi::Extent2D{16, 9}}) {
        const uint32_t w = size.width, h = size.height;
        AccumulateRig rig(w, h, {});
        FloatImage ref;
        uint32_t f = 0;
        // 1e12: the largest sanitised radiance (1e8) over a tiny albedo after demodulation.
        for (float v : {0.0f, 1e-30f, 65504.0f, 1e6f, 1e12f}) {
            INFO(w << "x" << h << " value " << v);
            auto input = makeImage(w, h, 4, [&](uint32_t x, uint32_t y, uint32_t) {
                return (x * 7 + y * 3 + f) % 5 == 0 ? v : 0.01f;
            });
            auto decision = randomDecisions(w, h, 900 + f);
            auto gpu = rig.frame(input, decision);
            ref = reference::bmfrAccumulate(input, decision, ref, {}, f > 0);
            requireAccumulateMatch(gpu, ref);
            ++f;
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("bmfr accumulate rejects a weight of 0, below 0 or above 1", "[bmfr][bmfr-accumulate]") {
    for (float bad : {0.0f, -0.1f, 1.5f, std::nanf("")}) {
        INFO("minWeight " << bad);
        REQUIRE_THROWS_AS(passes::bmfrAccumulateCountCap({.minWeight = bad}), Error);
    }
    REQUIRE(passes::bmfrAccumulateCountCap({.minWeight = 1.0f}) == 1);
    REQUIRE(passes::bmfrAccumulateCountCap({.minWeight = 0.3f}) == 4);
}
