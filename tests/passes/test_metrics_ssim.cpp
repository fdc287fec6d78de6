// passes/metrics/ssim: mean SSIM on the GPU against the double-precision CPU
// reference (map and mean), closed forms, small images, non-finite windows, extremes.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <hush/passes/metrics/partial_sums.hpp>
#include <hush/passes/metrics/ssim.hpp>

#include "reference/metrics_ssim.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

struct GpuSsim {
    passes::SsimResult result;
    FloatImage map;
};

GpuSsim gpuSsim(const FloatImage& image, const FloatImage& reference, const passes::MetricsSettings& settings = {}) {
    NodeHarness h({image.width, image.height}, "metrics-ssim");
    auto out = passes::addSsimPass(h.ctx, "metrics.ssim", h.input("image", image), h.input("reference", reference),
                                   settings);
    h.graph.markOutput(out.map);
    h.graph.execute();
    h.graph.waitIdle();
    return {passes::ssimFromPartials(passes::readPartials(test::gpu().device, h.graph, out.partials)),
            readOutput(h.graph, out.map)};
}

reference::SsimResult cpuSsim(const FloatImage& image, const FloatImage& reference) {
    return reference::ssim(image, reference, 0.01, 0.03, 1.0, 1.5);
}

// A reference in [0, scale) and a noisy image near it (SSIM well inside (0, 1)).
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

// The shader evaluates each window in fp32 (121 weighted taps, centred moments); the
// reference in double. Measured on lavapipe over sizes 1x1 .. 257x131 and values up
// to 1e6 (docs/passes/metrics.md): per window 6.6e-7, the mean 1.7e-7. A wrong window
// (one tap, the clipping, the normalisation) moves SSIM by 1e-3 or more.
constexpr float kMapTol = 1e-5f;
constexpr double kMeanTol = 1e-5;

} // namespace

TEST_CASE("ssim matches the CPU reference at every size", "[metrics][ssim]") {
    test::ValidationScope scope;
    const rhi::Extent2D sizes[] = {{1, 1}, {3, 5}, {11, 11}, {12, 13}, {64, 64}, {257, 131}, {3, 40}};
    uint64_t seed = 100;
    for (auto size : sizes) {
        INFO("size " << size.width << "x" << size.height);
        const auto pair = noisyPair(size.width, size.height, seed += 2);
        const auto gpu = gpuSsim(pair.image, pair.reference);
        const auto ref = cpuSsim(pair.image, pair.reference);
        INFO("gpu " << gpu.result.ssim << ", reference " << ref.ssim);
        CHECK(gpu.result.windows == ref.windows);
        CHECK(gpu.result.excludedWindows == 0);
        CHECK(gpu.result.ssim == Approx(ref.ssim).margin(kMeanTol));
        if (size.width * size.height > 1) {   // neither identical nor unrelated (1x1: luminance only)
            CHECK(ref.ssim > 0.05);
            CHECK(ref.ssim < 0.95);
        }
        HUSH_REQUIRE_IMAGES_MATCH(gpu.map, ref.map, kMapTol, 0.0f);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("ssim counts the valid window positions", "[metrics][ssim]") {
    test::ValidationScope scope;
    // (w - 10)(h - 10) positions when both sides are >= 11; every pixel along a shorter side.
    struct Case {
        uint32_t w, h;
        uint64_t windows;
    };
    for (Case c : {Case{11, 11, 1}, Case{12, 13, 6}, Case{64, 64, 54 * 54}, Case{3, 5, 15}, Case{3, 40, 90},
                   Case{1, 1, 1}}) {
        const FloatImage a(c.w, c.h, 4, 0.5f);
        CHECK(gpuSsim(a, a).result.windows == c.windows);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("ssim closed forms: identical, constant and scaled images", "[metrics][ssim]") {
    test::ValidationScope scope;
    const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
    SECTION("identical images give 1 at every size") {
        for (rhi::Extent2D size : {rhi::Extent2D{1, 1}, {3, 5}, {12, 13}, {64, 64}}) {
            const auto image = randomImage(size.width, size.height, 4, 0.0f, 1.0f, 7 + size.width);
            CHECK(gpuSsim(image, image).result.ssim == Approx(1.0).margin(1e-6));
        }
    }
    SECTION("two constant images: the luminance term only") {
        // Per channel, variances and covariance are 0, so the contrast-structure factor
        // is C2 / C2 = 1 and SSIM = (2ab + C1) / (a^2 + b^2 + C1); the mean is over RGB.
        const float a[3] = {0.5f, 0.25f, 1.0f}, b[3] = {0.25f, 0.25f, 0.0f};
        auto fill = [](const float* v) {
            return makeImage(12, 13, 4, [v](uint32_t, uint32_t, uint32_t c) { return c < 3 ? v[c] : 1.0f; });
        };
        double expected = 0;
        for (int c = 0; c < 3; ++c)
            expected += (2.0 * a[c] * b[c] + c1) / (double(a[c]) * a[c] + double(b[c]) * b[c] + c1) / 3.0;
        // (0.2501 / 0.3126 + 1 + 0.0001 / 1.0001) / 3 = 0.600056...
        CHECK(gpuSsim(fill(a), fill(b)).result.ssim == Approx(expected).margin(1e-6));
        // A 1x1 image: one position, the window is the pixel itself, same formula.
        const FloatImage one(1, 1, 4, 0.5f), other(1, 1, 4, 0.25f);
        CHECK(gpuSsim(one, other).result.ssim == Approx((0.25 + c1) / (0.3125 + c1)).margin(1e-6));
    }
    SECTION("a checkerboard against itself scaled") {
        // x = m + d (-1)^(i+j), y = s x. Over a full window with separable weights g
        // (sum G), the mean is m + d (-1)^(cx+cy) r^2 with r = sum (-1)^k g(k) / G, the
        // variance d^2 (1 - r^4) at every position; y has mean s mu, variance s^2 var,
        // covariance s var. So SSIM = (2 s mu^2 + C1) / ((1 + s^2) mu^2 + C1)
        //                          * (2 s var + C2) / ((1 + s^2) var + C2).
        const double m = 0.5, d = 0.25, s = 0.5;
        double g = 0, alternating = 0;
        for (int k = -5; k <= 5; ++k) {
            const double gk = std::exp(-k * k / (2 * 1.5 * 1.5));
            g += gk;
            alternating += (k % 2 == 0 ? 1 : -1) * gk;
        }
        const double r2 = (alternating / g) * (alternating / g);
        const double var = d * d * (1 - r2 * r2);
        auto windowSsim = [&](double mu) {
            return (2 * s * mu * mu + c1) / ((1 + s * s) * mu * mu + c1) * (2 * s * var + c2) /
                   ((1 + s * s) * var + c2);
        };
        for (rhi::Extent2D size : {rhi::Extent2D{11, 11}, {12, 13}, {64, 64}}) {
            auto x = makeImage(size.width, size.height, 4, [&](uint32_t i, uint32_t j, uint32_t) {
                return float(m + d * ((i + j) % 2 == 0 ? 1 : -1));
            });
            auto y = makeImage(size.width, size.height, 4,
                               [&](uint32_t i, uint32_t j, uint32_t c) { return float(s) * x.at(i, j, c); });
            double expected = 0;
            int positions = 0;
            for (uint32_t cy = 5; cy + 5 < size.height; ++cy)
                for (uint32_t cx = 5; cx + 5 < size.width; ++cx, ++positions)
                    expected += windowSsim(m + d * ((cx + cy) % 2 == 0 ? 1 : -1) * r2);
            expected /= positions;
            INFO("size " << size.width << "x" << size.height << ", expected " << expected);
            CHECK(gpuSsim(x, y).result.ssim == Approx(expected).margin(1e-6));
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("ssim leaves out and counts windows with non-finite values", "[metrics][ssim]") {
    test::ValidationScope scope;
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    auto pair = noisyPair(40, 30, 200);
    pair.image.at(20, 15, 1) = nan;      // inside 11 x 11 = 121 window positions
    pair.reference.at(0, 0, 2) = inf;    // in the one window at (5, 5)
    pair.image.at(30, 20, 3) = nan;      // alpha: ignored
    const auto gpu = gpuSsim(pair.image, pair.reference);
    const auto ref = cpuSsim(pair.image, pair.reference);
    CHECK(ref.excludedWindows == 122);
    CHECK(gpu.result.excludedWindows == ref.excludedWindows);
    CHECK(gpu.result.windows == ref.windows);
    CHECK(std::isfinite(gpu.result.ssim));
    CHECK(gpu.result.ssim == Approx(ref.ssim).margin(kMeanTol));
    HUSH_REQUIRE_IMAGES_MATCH(gpu.map, ref.map, kMapTol, 0.0f);

    // Small image: every clipped window of a 3x3 image holds the NaN in its middle.
    FloatImage small(3, 3, 4, 0.5f);
    small.at(1, 1, 0) = nan;
    auto error = test::errorFrom([&] { gpuSsim(small, FloatImage(3, 3, 4, 0.5f)); });
    REQUIRE(error);
    CHECK_THAT(error->what(), Catch::Contains("9 windows"));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("ssim at extreme values", "[metrics][ssim]") {
    test::ValidationScope scope;
    SECTION("all zero gives 1") {
        const FloatImage zero(13, 12, 4, 0.0f);
        CHECK(gpuSsim(zero, zero).result.ssim == 1.0);
    }
    SECTION("1e-30 is a constant 0 to SSIM's C1, C2: 1") {
        const auto pair = noisyPair(13, 12, 300, 1e-30f);
        CHECK(gpuSsim(pair.image, pair.reference).result.ssim == Approx(1.0).margin(1e-6));
        CHECK(cpuSsim(pair.image, pair.reference).ssim == Approx(1.0).margin(1e-6));
    }
    for (float scale : {65504.0f, 1e6f}) {
        DYNAMIC_SECTION("values up to " << scale << " (centred moments: no fp32 cancellation)") {
            const auto pair = noisyPair(23, 17, 400, scale);
            const auto gpu = gpuSsim(pair.image, pair.reference);
            const auto ref = cpuSsim(pair.image, pair.reference);
            CHECK(gpu.result.ssim == Approx(ref.ssim).margin(kMeanTol));
            HUSH_REQUIRE_IMAGES_MATCH(gpu.map, ref.map, kMapTol, 0.0f);
        }
    }
    SECTION("1e30 overflows mu^2 in fp32: an error, not a NaN") {
        // Inf / Inf in the luminance term (the true SSIM is 1).
        const FloatImage huge(12, 12, 4, 1e30f);
        auto error = test::errorFrom([&] { gpuSsim(huge, huge); });
        REQUIRE(error);
        CHECK_THAT(error->what(), Catch::Contains("overflowed"));
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("ssim rejects invalid settings", "[metrics][ssim]") {
    const FloatImage a(4, 4, 4, 0.5f);
    for (auto [settings, name] :
         {std::pair{passes::MetricsSettings{.ssimK1 = 0.0f}, "ssimK1"},
          std::pair{passes::MetricsSettings{.ssimK2 = -1.0f}, "ssimK2"},
          std::pair{passes::MetricsSettings{.ssimDynamicRange = std::numeric_limits<float>::infinity()},
                    "ssimDynamicRange"},
          std::pair{passes::MetricsSettings{.ssimSigma = 0.0f}, "ssimSigma"},
          std::pair{passes::MetricsSettings{.ssimK1 = 1e-30f}, "ssimC1"}}) {
        NodeHarness h({4, 4}, "metrics-ssim-settings");
        auto image = h.input("image", a);
        auto error = test::errorFrom([&] { passes::addSsimPass(h.ctx, "metrics.ssim", image, image, settings); });
        REQUIRE(error);
        CHECK_THAT(error->what(), Catch::Contains(name));
    }
}
