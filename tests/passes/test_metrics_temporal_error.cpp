// passes/metrics/temporal_error: SVGF's temporal error (Sec. 5.4) on the GPU against
// the double-precision CPU reference, a hand-worked value, non-finite pixels.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <hush/passes/metrics/partial_sums.hpp>
#include <hush/passes/metrics/temporal_error.hpp>

#include "reference/metrics_temporal_error.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

passes::TemporalError gpuTemporalError(const FloatImage& current, const FloatImage& previous) {
    NodeHarness h({current.width, current.height}, "metrics-temporal");
    auto partials = passes::addTemporalErrorPass(h.ctx, "metrics.temporal", h.input("current", current),
                                                 h.input("previous", previous));
    h.graph.execute();
    h.graph.waitIdle();
    return passes::temporalErrorFromPartials(passes::readPartials(test::gpu().device, h.graph, partials));
}

// fp32 partial sums added in double (as error metrics): measured worst relative
// difference 7.3e-8 on lavapipe (docs/passes/metrics.md).
constexpr double kRelTol = 1e-5;

} // namespace

TEST_CASE("temporal error matches the CPU reference at every size", "[metrics][temporal]") {
    test::ValidationScope scope;
    const rhi::Extent2D sizes[] = {{1, 1}, {3, 5}, {11, 11}, {12, 13}, {64, 64}, {257, 131}, {3, 520}};
    uint64_t seed = 500;
    for (auto size : sizes) {
        INFO("size " << size.width << "x" << size.height);
        const auto current = randomImage(size.width, size.height, 4, 0.0f, 1.0f, seed += 2);
        const auto previous = randomImage(size.width, size.height, 4, 0.0f, 1.0f, seed + 1);
        const auto gpu = gpuTemporalError(current, previous);
        const auto ref = reference::temporalError(current, previous);
        CHECK(gpu.pixels == ref.pixels);
        CHECK(gpu.error == Approx(ref.error).epsilon(kRelTol));
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("temporal error of constant frames, by hand", "[metrics][temporal]") {
    test::ValidationScope scope;
    auto constant = [](float r, float g, float b, float a) {
        const float rgba[4] = {r, g, b, a};
        return makeImage(12, 13, 4, [=](uint32_t, uint32_t, uint32_t c) { return rgba[c]; });
    };
    // |(0.75, 0.25, 0.5) - (0.5, 0.5, 0.5)| = (0.25, 0.25, 0): 0.25 * (0.2126 + 0.7152).
    // The luminance of the signed difference would be 0.25 * (0.2126 - 0.7152) < 0.
    const auto current = constant(0.75f, 0.25f, 0.5f, 1.0f), previous = constant(0.5f, 0.5f, 0.5f, 0.0f);
    CHECK(gpuTemporalError(current, previous).error == Approx(0.25 * (0.2126 + 0.7152)).epsilon(1e-6));
    CHECK(gpuTemporalError(previous, current).error == Approx(0.23195).epsilon(1e-6));
    CHECK(gpuTemporalError(current, current).error == 0.0);
    // A blue-only change weighs 0.0722.
    CHECK(gpuTemporalError(constant(0.5f, 0.5f, 1.5f, 1.0f), previous).error == Approx(0.0722).epsilon(1e-6));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("temporal error leaves out and counts non-finite pixels", "[metrics][temporal]") {
    test::ValidationScope scope;
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    auto current = randomImage(9, 7, 4, 0.0f, 1.0f, 600);
    auto previous = randomImage(9, 7, 4, 0.0f, 1.0f, 601);
    current.at(1, 1, 0) = nan;
    previous.at(8, 6, 1) = -inf;
    current.at(4, 4, 3) = inf;   // alpha: ignored
    const auto gpu = gpuTemporalError(current, previous);
    const auto ref = reference::temporalError(current, previous);
    CHECK(gpu.nonFinitePixels == 2);
    CHECK(gpu.pixels == 61);
    CHECK(gpu.error == Approx(ref.error).epsilon(kRelTol));

    FloatImage allInf(2, 2, 4, inf);
    auto error = test::errorFrom([&] { gpuTemporalError(allInf, allInf); });
    REQUIRE(error);
    CHECK_THAT(error->what(), Catch::Contains("4 pixels"));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("temporal error at extreme values", "[metrics][temporal]") {
    test::ValidationScope scope;
    const FloatImage zero(5, 5, 4, 0.0f);
    CHECK(gpuTemporalError(zero, zero).error == 0.0);
    for (float scale : {1e-30f, 65504.0f, 1e6f}) {
        INFO("scale " << scale);
        const auto current = randomImage(19, 11, 4, 0.0f, scale, 700);
        const auto previous = randomImage(19, 11, 4, 0.0f, scale, 701);
        CHECK(gpuTemporalError(current, previous).error ==
              Approx(reference::temporalError(current, previous).error).epsilon(kRelTol).margin(1e-36));
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
