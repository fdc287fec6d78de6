// passes/common/tonemap: the three curves against the CPU reference, the public CPU
// twins against the same reference, monotonicity and the extremes.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include <hush/passes/common/tonemap.hpp>

#include "reference/common_tonemap.hpp"

using namespace hush;
using namespace hush::passes_test;
using passes::TonemapOperator;
using passes::TonemapSettings;

namespace {

const TonemapOperator kOperators[] = {TonemapOperator::AcesFit, TonemapOperator::ReinhardLuminance,
                                      TonemapOperator::ReinhardPerChannel};

// Values spread over 20 decades (1e-12 .. 1e8): log-uniform, with some zeros.
FloatImage hdrImage(uint32_t w, uint32_t h, uint64_t seed) {
    auto exponents = randomImage(w, h, 3, -12.0f, 8.0f, seed);
    return makeImage(w, h, 3, [&](uint32_t x, uint32_t y, uint32_t c) {
        return (x + y + c) % 11 == 0 ? 0.0f : std::pow(10.0f, exponents.at(x, y, c));
    });
}

FloatImage runTonemap(const FloatImage& radiance, const TonemapSettings& settings) {
    NodeHarness t({radiance.width, radiance.height});
    auto out = passes::addTonemapPass(t.ctx, "tonemap", t.input("radiance", radiance), settings);
    return t.runOnce(out);
}

} // namespace

TEST_CASE("tonemap matches the CPU reference for each operator and exposure", "[common][tonemap]") {
    test::ValidationScope scope;
    const uint32_t w = 41, h = 27;
    auto radiance = hdrImage(w, h, 21);
    for (auto op : kOperators)
        for (float exposure : {1.0f, 0.6f, 3.5f}) {
            const TonemapSettings settings{.op = op, .exposure = exposure};
            INFO("operator " << uint32_t(op) << ", exposure " << exposure);
            auto gpu = runTonemap(radiance, settings);
            // fp32 shader vs double reference: a rational function of fp32 inputs, a
            // few ulps of a value <= 1 (measured worst: see docs/passes/display.md).
            HUSH_REQUIRE_IMAGES_MATCH(gpu, reference::tonemap(radiance, settings), 1e-6f, 1e-6f, 3);
            for (uint32_t y = 0; y < h; ++y)
                for (uint32_t x = 0; x < w; ++x) REQUIRE(gpu.at(x, y, 3) == 1.0f);
        }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("tonemap's public CPU functions match the reference and the known values", "[common][tonemap]") {
    // Narkowicz 2016: f(1) = 2.54 / 3.16 (pre-exposed: 1 maps to ~0.8).
    CHECK(passes::tonemapAcesFit(1.0f) == Approx(2.54 / 3.16).epsilon(1e-6));
    CHECK(passes::tonemapAcesFit(0.0f) == 0.0f);
    CHECK(passes::tonemapReinhard(1.0f) == 0.5f);
    const float white[3] = {1.0f, 1.0f, 1.0f};
    CHECK(passes::tonemapLuminance(white) == Approx(1.0f).epsilon(1e-6));
    auto radiance = hdrImage(23, 19, 22);
    for (auto op : kOperators)
        for (float exposure : {1.0f, 0.6f, 3.5f}) {
            const TonemapSettings settings{.op = op, .exposure = exposure};
            INFO("operator " << uint32_t(op) << ", exposure " << exposure);
            FloatImage cpu(radiance.width, radiance.height, 4, 1.0f);
            for (uint32_t y = 0; y < radiance.height; ++y)
                for (uint32_t x = 0; x < radiance.width; ++x) {
                    float rgb[3] = {radiance.at(x, y, 0), radiance.at(x, y, 1), radiance.at(x, y, 2)};
                    passes::tonemap(settings, rgb);
                    for (uint32_t c = 0; c < 3; ++c) cpu.at(x, y, c) = rgb[c];
                }
            // The same fp32 formula as the shader: as close as the GPU is.
            HUSH_REQUIRE_IMAGES_MATCH(cpu, reference::tonemap(radiance, settings), 1e-6f, 1e-6f, 3);
        }
}

TEST_CASE("tonemap is monotone in each channel and in luminance", "[common][tonemap]") {
    test::ValidationScope scope;
    // A grey ramp and a saturated-red ramp, 0 and then 1e-9 .. 1e9 log-spaced, along x.
    const uint32_t w = 128, h = 2;
    auto ramp = makeImage(w, h, 3, [](uint32_t x, uint32_t y, uint32_t c) {
        const float v = x == 0 ? 0.0f : std::pow(10.0f, -9.0f + 18.0f * float(x - 1) / float(w - 2));
        return y == 0 || c == 0 ? v : 0.05f * v;
    });
    for (auto op : kOperators) {
        INFO("operator " << uint32_t(op));
        auto gpu = runTonemap(ramp, {.op = op});
        for (uint32_t y = 0; y < h; ++y) {
            CHECK(gpu.at(0, y, 0) == 0.0f);
            for (uint32_t x = 1; x < w; ++x)
                for (uint32_t c = 0; c < 3; ++c) {
                    INFO("x " << x << " y " << y << " c " << c);
                    // Up to fp32 rounding: grey through the luminance operator is
                    // v / (1 + L(v)), a ratio of two roundings near saturation.
                    REQUIRE(gpu.at(x, y, c) >= gpu.at(x - 1, y, c) - 2e-7f);
                }
            CHECK(gpu.at(w - 1, y, 0) == Approx(1.0f).margin(1e-6));   // 1e9 saturates
        }
        // Strictly increasing somewhere in the middle (not a constant map).
        CHECK(gpu.at(64, 0, 1) > gpu.at(60, 0, 1));
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("tonemap maps 0 to 0 and 1e6, 65504 and FLT_MAX into [0, 1] at 1x1, 3x5 and 257x131",
          "[common][tonemap]") {
    test::ValidationScope scope;
    const float extremes[] = {0.0f, 1e-30f, 65504.0f, 1e6f, 1e8f, 3.4e38f};
    for (auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{3, 5}, rhi::Extent2D{257, 131}}) {
        auto radiance = makeImage(size.width, size.height, 3, [&](uint32_t x, uint32_t y, uint32_t c) {
            return extremes[(x * 7 + y * 3 + c) % 6];
        });
        for (auto op : kOperators)
            for (float exposure : {1.0f, 1e6f}) {
                INFO(size.width << "x" << size.height << ", operator " << uint32_t(op) << ", exposure " << exposure);
                const TonemapSettings settings{.op = op, .exposure = exposure};
                auto gpu = runTonemap(radiance, settings);
                REQUIRE(nonFiniteCount(gpu) == 0);
                // Same tolerance as above: the clamps before the curves change nothing visible.
                HUSH_REQUIRE_IMAGES_MATCH(gpu, reference::tonemap(radiance, settings), 1e-6f, 1e-6f, 3);
                size_t outOfRange = 0, zeroNotKept = 0, notSaturated = 0;
                for (uint32_t y = 0; y < size.height; ++y)
                    for (uint32_t x = 0; x < size.width; ++x)
                        for (uint32_t c = 0; c < 3; ++c) {
                            const float in = radiance.at(x, y, c), out = gpu.at(x, y, c);
                            outOfRange += out >= 0.0f && out <= 1.0f ? 0 : 1;
                            zeroNotKept += in == 0.0f && out != 0.0f ? 1 : 0;
                            notSaturated += in >= 65504.0f && op == TonemapOperator::AcesFit && out != 1.0f ? 1 : 0;
                        }
                CHECK(outOfRange == 0);
                CHECK(zeroNotKept == 0);
                CHECK(notSaturated == 0);
                // All-zero pixels stay black with every operator.
                auto black = runTonemap(FloatImage(size.width, size.height, 3, 0.0f), settings);
                HUSH_REQUIRE_IMAGES_MATCH(black, FloatImage(size.width, size.height, 3, 0.0f), 0.0f, 0.0f, 3);
            }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
