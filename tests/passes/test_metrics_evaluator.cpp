// passes/metrics/metrics_evaluator: the tools' entry point. Its results equal the
// CPU references, it re-uploads per call, and names the argument of a wrong size.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <hush/passes/metrics/metrics_evaluator.hpp>

#include "reference/metrics_error_metrics.hpp"
#include "reference/metrics_ssim.hpp"
#include "reference/metrics_temporal_error.hpp"

using namespace hush;
using namespace hush::passes_test;

TEST_CASE("metrics evaluator matches the CPU references and re-uploads per call", "[metrics][evaluator]") {
    test::ValidationScope scope;
    const uint32_t w = 37, h = 29;
    passes::MetricsEvaluator evaluator(test::gpu().device, {w, h});
    for (uint64_t seed : {800u, 810u}) {
        INFO("seed " << seed);
        const auto reference = randomImage(w, h, 4, 0.0f, 1.0f, seed);
        auto image = reference;
        const auto noise = randomImage(w, h, 4, -0.1f, 0.1f, seed + 1);
        for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] += noise.pixels[i];

        const auto m = evaluator.compare(image.pixels, reference.pixels);
        const auto error = reference::errorMetrics(image, reference, 0.01, 1.0);
        const auto ssim = reference::ssim(image, reference, 0.01, 0.03, 1.0, 1.5);
        CHECK(m.rmse == Approx(error.rmse).epsilon(1e-5));
        CHECK(m.relMse == Approx(error.relMse).epsilon(1e-5));
        CHECK(m.psnr == Approx(error.psnr).margin(1e-4));
        CHECK(m.ssim == Approx(ssim.ssim).margin(1e-5));
        CHECK(m.nonFinitePixels == 0);
        CHECK(m.excludedSsimWindows == 0);

        const double temporal = evaluator.temporalError(image.pixels, reference.pixels);
        CHECK(temporal == Approx(reference::temporalError(image, reference).error).epsilon(1e-5));
        CHECK(evaluator.lastTemporalError().pixels == size_t(w) * h);
    }
    const auto same = randomImage(w, h, 4, 0.0f, 1.0f, 900);
    const auto identical = evaluator.compare(same.pixels, same.pixels);
    CHECK(identical.rmse == 0.0);
    CHECK(identical.psnr == std::numeric_limits<double>::infinity());
    CHECK(identical.ssim == Approx(1.0).margin(1e-6));

    const auto order = evaluator.graph().passOrder();
    for (const char* pass : {"metrics.error", "metrics.ssim.map", "metrics.ssim.reduce"})
        CHECK(std::find(order.begin(), order.end(), pass) != order.end());
    CHECK(evaluator.temporalGraph().passOrder() == std::vector<std::string>{"metrics.temporal"});
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("metrics evaluator counts non-finite pixels and names wrong arguments", "[metrics][evaluator]") {
    test::ValidationScope scope;
    const uint32_t w = 24, h = 20;
    passes::MetricsEvaluator evaluator(test::gpu().device, {w, h});
    auto image = randomImage(w, h, 4, 0.0f, 1.0f, 1000);
    const auto reference = randomImage(w, h, 4, 0.0f, 1.0f, 1001);
    image.at(8, 6, 0) = std::numeric_limits<float>::quiet_NaN();
    const auto m = evaluator.compare(image.pixels, reference.pixels);
    CHECK(m.nonFinitePixels == 1);
    CHECK(m.excludedSsimWindows == 9 * 7);   // of 14 x 10 centres, 5..13 x 5..11 hold (8, 6)
    CHECK(std::isfinite(m.rmse));
    CHECK(std::isfinite(m.ssim));
    CHECK(m.rmse == Approx(reference::errorMetrics(image, reference, 0.01, 1.0).rmse).epsilon(1e-5));
    CHECK(m.ssim == Approx(reference::ssim(image, reference, 0.01, 0.03, 1.0, 1.5).ssim).margin(1e-5));
    CHECK(std::isfinite(evaluator.temporalError(image.pixels, reference.pixels)));
    CHECK(evaluator.lastTemporalError().nonFinitePixels == 1);

    std::vector<float> short_(size_t(w) * h * 4 - 1), rgb(size_t(w) * h * 3);
    auto badReference = test::errorFrom([&] { evaluator.compare(reference.pixels, short_); });
    REQUIRE(badReference);
    CHECK(badReference->kind() == ErrorKind::InvalidArgument);
    CHECK_THAT(badReference->what(), Catch::Contains("'reference'") && Catch::Contains("1920"));
    auto badImage = test::errorFrom([&] { evaluator.compare(rgb, reference.pixels); });
    REQUIRE(badImage);
    CHECK_THAT(badImage->what(), Catch::Contains("'image'"));
    auto badCurrent = test::errorFrom([&] { evaluator.temporalError(rgb, reference.pixels); });
    REQUIRE(badCurrent);
    CHECK_THAT(badCurrent->what(), Catch::Contains("'current'"));
    auto badPrevious = test::errorFrom([&] { evaluator.temporalError(reference.pixels, short_); });
    REQUIRE(badPrevious);
    CHECK_THAT(badPrevious->what(), Catch::Contains("'previous'"));
    // Still usable after a rejected call.
    CHECK(evaluator.compare(reference.pixels, reference.pixels).rmse == 0.0);

    auto empty = test::errorFrom([&] { passes::MetricsEvaluator(test::gpu().device, {0, 4}); });
    REQUIRE(empty);
    CHECK_THAT(empty->what(), Catch::Contains("empty"));
    auto badSettings = test::errorFrom(
        [&] { passes::MetricsEvaluator(test::gpu().device, {4, 4}, {.ssimSigma = -1.0f}); });
    REQUIRE(badSettings);
    CHECK_THAT(badSettings->what(), Catch::Contains("ssimSigma"));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
