// passes/metrics/error_metrics: RMSE, relative MSE and PSNR on the GPU against the
// double-precision CPU reference, hand-worked values, non-finite pixels, extremes.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <hush/passes/metrics/error_metrics.hpp>
#include <hush/passes/metrics/partial_sums.hpp>

#include "reference/metrics_error_metrics.hpp"
#include "support/half.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

passes::ErrorMetrics gpuErrorMetrics(const FloatImage& image, const FloatImage& reference,
                                     const passes::MetricsSettings& settings = {}) {
    NodeHarness h({image.width, image.height}, "metrics-error");
    auto partials = passes::addErrorMetricsPass(h.ctx, "metrics.error", h.input("image", image),
                                                h.input("reference", reference), settings);
    h.graph.execute();
    h.graph.waitIdle();
    return passes::errorMetricsFromPartials(passes::readPartials(test::gpu().device, h.graph, partials), settings);
}

// A reference in [0, 1] and an image near it; alpha differs (it must be ignored).
struct ImagePair {
    FloatImage image, reference;
};
ImagePair noisyPair(uint32_t w, uint32_t h, uint64_t seed, float scale = 1.0f) {
    auto reference = randomImage(w, h, 4, 0.0f, scale, seed);
    auto noise = randomImage(w, h, 4, -0.2f * scale, 0.2f * scale, seed + 1);
    auto image = reference;
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] += noise.pixels[i];
    return {image, reference};
}

// GPU partials are fp32 sums (per invocation, then a 256-way shared-memory tree),
// added in double on the host: relative error of a few fp32 ulps times log2 of the
// sum's length. Measured on lavapipe over sizes 1x1 .. 257x131 and values up to 1e6
// (docs/passes/metrics.md): RMSE 4e-8, relMSE 2.2e-7 relative, PSNR 3.2e-7 dB. The
// bounds leave headroom for other drivers' arithmetic; a real bug is far above them.
constexpr double kRelTol = 1e-5;

void requireMatches(const passes::ErrorMetrics& gpu, const reference::ErrorMetricsResult& ref) {
    INFO("gpu rmse " << gpu.rmse << " relMse " << gpu.relMse << " psnr " << gpu.psnr << "; reference rmse "
                     << ref.rmse << " relMse " << ref.relMse << " psnr " << ref.psnr);
    CHECK(gpu.pixels == ref.pixels);
    CHECK(gpu.nonFinitePixels == ref.nonFinitePixels);
    CHECK(gpu.rmse == Approx(ref.rmse).epsilon(kRelTol).margin(1e-12));
    CHECK(gpu.relMse == Approx(ref.relMse).epsilon(kRelTol).margin(1e-12));
    // 10 log10 turns a relative error e of the MSE into 4.34 e dB.
    CHECK(gpu.psnr == Approx(ref.psnr).margin(1e-4));
}

} // namespace

TEST_CASE("error metrics match the CPU reference at every size", "[metrics][error]") {
    test::ValidationScope scope;
    const rhi::Extent2D sizes[] = {{1, 1}, {3, 5}, {11, 11}, {12, 13}, {64, 64}, {257, 131}, {3, 520}};
    uint64_t seed = 10;
    for (auto size : sizes) {
        INFO("size " << size.width << "x" << size.height);
        const auto pair = noisyPair(size.width, size.height, seed += 2);
        const auto gpu = gpuErrorMetrics(pair.image, pair.reference);
        requireMatches(gpu, reference::errorMetrics(pair.image, pair.reference, 0.01, 1.0));
        CHECK(gpu.pixels == size_t(size.width) * size.height);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("error metrics of identical images and of a constant offset", "[metrics][error]") {
    test::ValidationScope scope;
    // Values k / 256: the offset 1/8 is exact in fp32, so the GPU sees exactly it.
    auto reference = makeImage(12, 13, 4, [](uint32_t x, uint32_t y, uint32_t c) {
        return float((x * 7 + y * 13 + c * 29) % 128 + 32) / 256.0f;
    });
    const auto same = gpuErrorMetrics(reference, reference);
    CHECK(same.rmse == 0.0);
    CHECK(same.relMse == 0.0);
    CHECK(same.psnr == std::numeric_limits<double>::infinity());

    auto offset = makeImage(12, 13, 4, [&](uint32_t x, uint32_t y, uint32_t c) {
        return reference.at(x, y, c) + (c < 3 ? 0.125f : 0.5f);   // alpha differs more: ignored
    });
    const auto shifted = gpuErrorMetrics(offset, reference);
    CHECK(shifted.rmse == Approx(0.125).epsilon(1e-6));
    CHECK(shifted.psnr == Approx(20.0 * std::log10(8.0)).margin(1e-5));   // 18.0618 dB

    // Any float format is read: the same values (exact in fp16) from an rgba16f image.
    auto fp16Image = test::gpu().device.createTexture(
        {.label = "image.fp16",
         .size = {12, 13},
         .format = Format::RGBA16Float,
         .usage = rhi::TextureUsage::TextureBinding | rhi::TextureUsage::CopyDst});
    std::vector<uint16_t> halves(offset.pixels.size());
    for (size_t i = 0; i < halves.size(); ++i) halves[i] = test::floatToHalf(offset.pixels[i]);
    test::gpu().queue().writeTexture({.texture = fp16Image, .data = test::bytesOf(halves)});
    NodeHarness h({12, 13}, "metrics-error-fp16");
    auto partials = passes::addErrorMetricsPass(h.ctx, "metrics.error", h.graph.importTexture("image", fp16Image),
                                                h.input("reference", reference));
    h.graph.execute();
    h.graph.waitIdle();
    CHECK(passes::errorMetricsFromPartials(passes::readPartials(test::gpu().device, h.graph, partials)).rmse ==
          Approx(0.125).epsilon(1e-6));

    // A constant 0.5 against a constant 0.25, by hand: every value has
    // (a - b)^2 / (b^2 + 0.01) = 0.0625 / 0.0725, and RMSE = 0.25.
    const FloatImage half(5, 3, 4, 0.5f), quarter(5, 3, 4, 0.25f);
    const auto constant = gpuErrorMetrics(half, quarter);
    CHECK(constant.relMse == Approx(0.0625 / 0.0725).epsilon(1e-6));
    CHECK(constant.rmse == Approx(0.25).epsilon(1e-6));
    // PSNR with peak 2: 10 log10(4 / 0.0625) = 18.0618 dB.
    CHECK(gpuErrorMetrics(half, quarter, {.psnrPeak = 2.0}).psnr == Approx(10.0 * std::log10(64.0)).margin(1e-5));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("error metrics leave out and count pixels with non-finite values", "[metrics][error]") {
    test::ValidationScope scope;
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    auto pair = noisyPair(17, 9, 40);
    pair.image.at(3, 2, 0) = nan;
    pair.image.at(16, 8, 2) = -inf;
    pair.reference.at(3, 2, 1) = inf;   // same pixel as a NaN: counted once
    pair.reference.at(0, 0, 1) = nan;
    pair.image.at(5, 5, 3) = nan;        // alpha: ignored, not counted
    const auto gpu = gpuErrorMetrics(pair.image, pair.reference);
    CHECK(gpu.nonFinitePixels == 3);
    CHECK(std::isfinite(gpu.rmse));
    requireMatches(gpu, reference::errorMetrics(pair.image, pair.reference, 0.01, 1.0));

    FloatImage allNan(4, 4, 4, nan), zero(4, 4, 4, 0.0f);
    auto error = test::errorFrom([&] { gpuErrorMetrics(allNan, zero); });
    REQUIRE(error);
    CHECK(error->kind() == ErrorKind::InvalidArgument);
    CHECK_THAT(error->what(), Catch::Contains("16 pixels") && Catch::Contains("finite"));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("error metrics at extreme values", "[metrics][error]") {
    test::ValidationScope scope;
    SECTION("all zero") {
        const FloatImage zero(7, 5, 4, 0.0f);
        const auto gpu = gpuErrorMetrics(zero, zero);
        CHECK(gpu.rmse == 0.0);
        CHECK(gpu.relMse == 0.0);
        CHECK(gpu.psnr == std::numeric_limits<double>::infinity());
    }
    SECTION("1e-30: squares underflow fp32, the metrics stay finite and tiny") {
        const auto pair = noisyPair(7, 5, 50, 1e-30f);
        const auto gpu = gpuErrorMetrics(pair.image, pair.reference);
        const auto ref = reference::errorMetrics(pair.image, pair.reference, 0.01, 1.0);
        CHECK(gpu.rmse == Approx(ref.rmse).margin(1e-18));
        CHECK(gpu.relMse == Approx(ref.relMse).margin(1e-18));
        CHECK(gpu.psnr > 300.0);   // +inf when the squares flush to 0; about 600 dB in double
    }
    for (float scale : {65504.0f, 1e6f}) {
        DYNAMIC_SECTION("values up to " << scale) {
            const auto pair = noisyPair(19, 11, 60, scale);
            requireMatches(gpuErrorMetrics(pair.image, pair.reference),
                           reference::errorMetrics(pair.image, pair.reference, 0.01, 1.0));
        }
    }
    SECTION("1e30 overflows the fp32 squares: an error, not a NaN") {
        const FloatImage huge(3, 3, 4, 1e30f), zero(3, 3, 4, 0.0f);
        auto error = test::errorFrom([&] { gpuErrorMetrics(huge, zero); });
        REQUIRE(error);
        CHECK_THAT(error->what(), Catch::Contains("overflowed"));
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("error metrics reject invalid settings and mismatched sizes", "[metrics][error]") {
    test::ValidationScope scope;
    const FloatImage a(4, 4, 4, 0.5f);
    auto badEpsilon = test::errorFrom([&] { gpuErrorMetrics(a, a, {.relMseEpsilon = 0.0f}); });
    REQUIRE(badEpsilon);
    CHECK_THAT(badEpsilon->what(), Catch::Contains("relMseEpsilon"));
    auto badPeak = test::errorFrom([&] { gpuErrorMetrics(a, a, {.psnrPeak = std::nan("")}); });
    REQUIRE(badPeak);
    CHECK_THAT(badPeak->what(), Catch::Contains("psnrPeak"));

    NodeHarness h({4, 4}, "metrics-error-size");
    passes::addErrorMetricsPass(h.ctx, "metrics.error", h.input("image", a), h.input("reference", FloatImage(5, 4, 4)));
    auto mismatch = test::errorFrom([&] { h.graph.compile(); });
    REQUIRE(mismatch);
    CHECK_THAT(mismatch->what(), Catch::Contains("reference"));

    std::vector<float> wrongCount(10);
    auto partials = test::errorFrom([&] { passes::errorMetricsFromPartials(wrongCount); });
    REQUIRE(partials);
    CHECK_THAT(partials->what(), Catch::Contains("partial sums"));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
