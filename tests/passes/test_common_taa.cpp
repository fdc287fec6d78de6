// passes/common/taa: Karis 2014 TAA against the CPU reference over several frames
// (static, sub-pixel and out-of-screen motion, reset), rectification of a history
// colour outside the neighbourhood, the extremes and odd sizes; each history filter.
// The history filters' and the reprojection decision's own properties:
// test_common_taa_history.cpp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <hush/passes/common/taa.hpp>

#include "reference/common_taa.hpp"
#include "taa_test_graph.hpp"

using namespace hush;
using namespace hush::passes_test;
using passes::TaaBox;
using passes::TaaHistoryFilter;
using passes::TaaRectify;
using passes::TaaSettings;

namespace {

// Every box / rectification pair, each history filter; alpha varies too.
const TaaSettings kSettings[] = {
    {},   // the defaults: Karis 2014 (min/max box, clip, alpha 0.1) with Catmull-Rom history
    {.historyFilter = TaaHistoryFilter::Bilinear},   // Karis 2014 as published
    {.box = TaaBox::MinMax, .rectify = TaaRectify::Clamp},
    {.box = TaaBox::Variance, .rectify = TaaRectify::Clip, .historyFilter = TaaHistoryFilter::Bilinear},
    {.alpha = 0.5f, .box = TaaBox::Variance, .rectify = TaaRectify::Clamp, .varianceGamma = 1.5f},
};

// The fp32 shader against the double reference, each frame. The history feeds back,
// but the blend shrinks last frame's error by (1 - alpha), so errors do not grow;
// measured worst over these tests: see docs/passes/display.md.
constexpr float kAbsTol = 2e-6f, kRelTol = 2e-6f;

// Runs `frames` frames of random display colours (scaled by `scale`, with some
// zeros) on GPU and reference, comparing each frame; returns the last GPU frame.
// With a `decision`, the node reads its history through it.
FloatImage compareOverFrames(rhi::Extent2D size, const TaaSettings& settings, const FloatImage& motion,
                             uint32_t frames, float scale = 1.0f, float absTol = kAbsTol,
                             const FloatImage& decision = {}) {
    TaaGraph gpu(size, settings, !decision.pixels.empty());
    reference::Taa ref(settings);
    FloatImage last;
    for (uint32_t f = 0; f < frames; ++f) {
        auto current = randomImage(size.width, size.height, 4, 0.0f, scale, 100 + f);
        for (size_t i = 0; i < current.pixels.size(); i += 7) current.pixels[i] = 0.0f;
        INFO("frame " << f);
        last = gpu.frame(current, motion, decision);
        REQUIRE(nonFiniteCount(last) == 0);
        HUSH_REQUIRE_IMAGES_MATCH(last, ref.frame(current, motion, decision), absTol, kRelTol, 3);
        if (f == 0) HUSH_REQUIRE_IMAGES_MATCH(last, current, 0.0f, 0.0f, 3);   // no history: current, exactly
    }
    return last;
}

std::vector<double> toYCoCg(const FloatImage& image, uint32_t x, uint32_t y) {
    const double r = image.at(x, y, 0), g = image.at(x, y, 1), b = image.at(x, y, 2);
    return {(r + 2 * g + b) / 4, (r - b) / 2, (2 * g - r - b) / 4};
}

} // namespace

TEST_CASE("TAA matches the CPU reference over frames with a static camera", "[common][taa]") {
    test::ValidationScope scope;
    const rhi::Extent2D size{29, 17};
    for (const auto& settings : kSettings) {
        INFO(describe(settings));
        compareOverFrames(size, settings, constantMotion(size, 0.0f, 0.0f), 6);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("TAA matches the CPU reference over frames with sub-pixel motion", "[common][taa]") {
    test::ValidationScope scope;
    const rhi::Extent2D size{31, 19};
    auto jitter = randomImage(size.width, size.height, 2, -1.5f, 1.5f, 7);
    auto motion = makeImage(size.width, size.height, 2, [&](uint32_t x, uint32_t y, uint32_t c) {
        return (c == 0 ? 0.25f : -0.375f) + (x > 20 ? jitter.at(x, y, c) : 0.0f);
    });
    for (const auto& settings : kSettings) {
        INFO(describe(settings));
        compareOverFrames(size, settings, motion, 6);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("TAA outputs the current colour where the motion leaves the screen", "[common][taa]") {
    test::ValidationScope scope;
    const rhi::Extent2D size{23, 13};
    // Previous position = centre + (-3.25, 2): x <= 2 is off the left edge, y >= 11 off the bottom.
    auto motion = constantMotion(size, -3.25f, 2.0f);
    TaaGraph gpu(size, {});
    reference::Taa ref({});
    for (uint32_t f = 0; f < 4; ++f) {
        auto current = randomImage(size.width, size.height, 4, 0.0f, 1.0f, 200 + f);
        auto out = gpu.frame(current, motion);
        INFO("frame " << f);
        HUSH_REQUIRE_IMAGES_MATCH(out, ref.frame(current, motion), kAbsTol, kRelTol, 3);
        uint32_t historyPixels = 0;
        for (uint32_t y = 0; y < size.height; ++y)
            for (uint32_t x = 0; x < size.width; ++x) {
                const bool offScreen = x <= 2 || y >= 11;
                bool same = true;
                for (uint32_t c = 0; c < 3; ++c) same = same && out.at(x, y, c) == current.at(x, y, c);
                if (offScreen) REQUIRE(same);
                historyPixels += same ? 0 : 1;
            }
        // From the second frame on, the on-screen pixels do use their history.
        if (f > 0) CHECK(historyPixels > (size.width - 3) * (size.height - 2) / 2);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("TAA rectifies a history colour outside the current neighbourhood", "[common][taa]") {
    test::ValidationScope scope;
    const rhi::Extent2D size{16, 12};
    const auto still = constantMotion(size, 0.0f, 0.0f);
    // Frame 0: red everywhere. Frame 1: blue with a little noise. Without rectification
    // the output would be 0.9 * red + 0.1 * blue.
    auto red = makeImage(size.width, size.height, 4, [](uint32_t, uint32_t, uint32_t c) {
        return c == 0 ? 0.9f : 0.1f;
    });
    auto noise = randomImage(size.width, size.height, 4, -0.02f, 0.02f, 300);
    auto blue = makeImage(size.width, size.height, 4, [&](uint32_t x, uint32_t y, uint32_t c) {
        return (c == 2 ? 0.8f : 0.1f) + noise.at(x, y, c);
    });
    auto flatBlue = makeImage(size.width, size.height, 4, [](uint32_t, uint32_t, uint32_t c) {
        return c == 2 ? 0.8f : 0.1f;
    });
    for (const auto& settings : kSettings) {
        INFO(describe(settings));
        TaaGraph gpu(size, settings);
        reference::Taa ref(settings);
        gpu.frame(red, still);
        ref.frame(red, still);
        auto out = gpu.frame(blue, still);
        HUSH_REQUIRE_IMAGES_MATCH(out, ref.frame(blue, still), kAbsTol, kRelTol, 3);
        for (uint32_t y = 0; y < size.height; ++y)
            for (uint32_t x = 0; x < size.width; ++x) {
                REQUIRE(out.at(x, y, 0) < 0.2f);   // the red history did not survive
                if (settings.box != TaaBox::MinMax) continue;
                // Min/max box: the rectified history is inside the neighbourhood's YCoCg box,
                // and so is its blend with the (inside) current colour.
                const auto o = toYCoCg(out, x, y);
                for (uint32_t c = 0; c < 3; ++c) {
                    double lo = 1e9, hi = -1e9;
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx) {
                            const int nx = std::clamp(int(x) + dx, 0, int(size.width) - 1);
                            const int ny = std::clamp(int(y) + dy, 0, int(size.height) - 1);
                            const double v = toYCoCg(blue, uint32_t(nx), uint32_t(ny))[c];
                            lo = std::min(lo, v), hi = std::max(hi, v);
                        }
                    REQUIRE(o[c] >= lo - 1e-6);
                    REQUIRE(o[c] <= hi + 1e-6);
                }
            }
        // A flat neighbourhood is a point: the history collapses onto it.
        HUSH_REQUIRE_IMAGES_MATCH(gpu.frame(flatBlue, still), flatBlue, 1e-6f, 0.0f, 3);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("TAA forgets its history after resetHistory", "[common][taa]") {
    test::ValidationScope scope;
    const rhi::Extent2D size{13, 9};
    const auto motion = constantMotion(size, 0.5f, -0.25f);
    TaaGraph gpu(size, {});
    reference::Taa ref({});
    for (uint32_t f = 0; f < 6; ++f) {
        if (f == 3) {
            gpu.t.graph.resetHistory();
            ref.reset();
        }
        auto current = randomImage(size.width, size.height, 4, 0.0f, 1.0f, 400 + f);
        auto out = gpu.frame(current, motion);
        INFO("frame " << f);
        HUSH_REQUIRE_IMAGES_MATCH(out, ref.frame(current, motion), kAbsTol, kRelTol, 3);
        if (f == 0 || f == 3) HUSH_REQUIRE_IMAGES_MATCH(out, current, 0.0f, 0.0f, 3);
        else REQUIRE(!compareImages(out, current, 1e-3f, 0.0f, 3).empty());   // history in use
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("TAA stays finite and matches the reference at 0, 1e-30, 65504 and 1e6", "[common][taa]") {
    test::ValidationScope scope;
    const rhi::Extent2D size{19, 11};
    auto jitter = randomImage(size.width, size.height, 2, -1.0f, 1.0f, 500);
    SECTION("each magnitude alone, relative to its scale") {
        for (float scale : {1e-30f, 65504.0f, 1e6f})
            for (const auto& settings : kSettings) {
                INFO("scale " << scale << " " << describe(settings));
                // fp32 rounding of sums and differences of values of size `scale`.
                compareOverFrames(size, settings, jitter, 4, scale, 4e-6f * scale);
            }
    }
    SECTION("all-zero frames") {
        for (const auto& settings : kSettings) {
            TaaGraph gpu(size, settings);
            const FloatImage zero(size.width, size.height, 4, 0.0f);
            for (int f = 0; f < 3; ++f) HUSH_REQUIRE_IMAGES_MATCH(gpu.frame(zero, jitter), zero, 0.0f, 0.0f, 3);
        }
    }
    SECTION("magnitudes mixed tile by tile") {
        // 4x4 tiles of 0, 1e-30, 65504 and 1e6 (varied +-25 % per pixel and frame), so
        // that each pixel's tolerance can follow the magnitudes that reach it: fp32
        // rounding relative to the largest value in its 5x5 window over every frame so
        // far (the 3x3 neighbourhood plus the history's bilinear footprint). Zero tiles
        // must stay exactly zero and 1e-30 tiles within 1e-35, not within 1e6's ulp.
        const float values[] = {0.0f, 1e-30f, 65504.0f, 1e6f};
        auto tilePick = randomImage((size.width + 3) / 4, (size.height + 3) / 4, 1, 0.0f, 4.0f, 600);
        for (const auto& settings : kSettings) {
            INFO(describe(settings));
            TaaGraph gpu(size, settings);
            reference::Taa ref(settings);
            FloatImage reach(size.width, size.height, 1, 0.0f);   // largest magnitude within reach so far
            for (uint32_t f = 0; f < 4; ++f) {
                auto vary = randomImage(size.width, size.height, 4, 0.75f, 1.25f, 610 + f);
                auto current = makeImage(size.width, size.height, 4, [&](uint32_t x, uint32_t y, uint32_t c) {
                    return values[std::min(3, int(tilePick.at(x / 4, y / 4, 0)))] * vary.at(x, y, c);
                });
                for (uint32_t y = 0; y < size.height; ++y)
                    for (uint32_t x = 0; x < size.width; ++x)
                        for (int dy = -2; dy <= 2; ++dy)
                            for (int dx = -2; dx <= 2; ++dx) {
                                const int sx = std::clamp(int(x) + dx, 0, int(size.width) - 1);
                                const int sy = std::clamp(int(y) + dy, 0, int(size.height) - 1);
                                for (uint32_t c = 0; c < 3; ++c)
                                    reach.at(x, y, 0) = std::max(reach.at(x, y, 0), current.at(sx, sy, c));
                            }
                auto out = gpu.frame(current, jitter);
                const auto expected = ref.frame(current, jitter);
                REQUIRE(nonFiniteCount(out) == 0);
                INFO("frame " << f);
                size_t mismatches = 0;
                for (uint32_t y = 0; y < size.height; ++y)
                    for (uint32_t x = 0; x < size.width; ++x)
                        for (uint32_t c = 0; c < 3; ++c) {
                            const float tolerance = 1e-5f * reach.at(x, y, 0);
                            const float got = out.at(x, y, c), want = expected.at(x, y, c);
                            if (got >= 0.0f && std::abs(got - want) <= tolerance) continue;
                            if (mismatches++ == 0)
                                UNSCOPED_INFO("first mismatch at (" << x << ", " << y << ") channel " << c << ": GPU "
                                                                    << got << ", reference " << want
                                                                    << ", tolerance " << tolerance);
                        }
                REQUIRE(mismatches == 0);
            }
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("TAA matches the reference at 1x1, 3x5 and 257x131", "[common][taa]") {
    test::ValidationScope scope;
    for (auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{3, 5}, rhi::Extent2D{257, 131}}) {
        INFO(size.width << "x" << size.height);
        auto jitter = randomImage(size.width, size.height, 2, -0.4f, 0.4f, 700);
        for (const auto& settings : {kSettings[0], kSettings[3]}) compareOverFrames(size, settings, jitter, 4);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
