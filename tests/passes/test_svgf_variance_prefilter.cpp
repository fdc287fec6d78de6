// passes/svgf/variance_prefilter: the 3x3 Gaussian of the variance that steers SVGF's
// luminance weight (Schied et al. 2017, Sec. 4.4, Eq. 5), against the CPU reference.
#include <catch2/catch.hpp>

#include <hush/passes/svgf/variance_prefilter.hpp>

#include "reference/svgf_variance_prefilter.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {
// Nine fp32 multiply-adds and one division against double: a few ulps.
constexpr float kAbsTol = 0.0f, kRelTol = 1e-6f;

FloatImage prefilterOnGpu(const FloatImage& illumVariance) {
    NodeHarness t({illumVariance.width, illumVariance.height});
    return t.runOnce(passes::addSvgfVariancePrefilterPass(t.ctx, "prefilter", t.input("illum", illumVariance)));
}
} // namespace

TEST_CASE("svgf variance prefilter matches the CPU reference", "[svgf-atrous][svgf-prefilter]") {
    test::ValidationScope scope;
    for (auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{3, 5}, rhi::Extent2D{37, 23}, rhi::Extent2D{257, 131}}) {
        INFO(size.width << "x" << size.height);
        auto illum = randomImage(size.width, size.height, 4, 0.0f, 3.0f, 17);
        auto gpu = prefilterOnGpu(illum);
        REQUIRE(gpu.channels == 1);
        HUSH_REQUIRE_IMAGES_MATCH(gpu, reference::svgfVariancePrefilter(illum), kAbsTol, kRelTol);
        if (size.width == 1) CHECK(gpu.at(0, 0) == illum.at(0, 0, 3));
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("svgf variance prefilter: by hand, and a constant stays constant up to the border",
          "[svgf-atrous][svgf-prefilter]") {
    test::ValidationScope scope;
    // A single spike of 16 in a 5x5 zero image: its 3x3 neighbourhood gets the
    // Gaussian's weights (4, 2, 1) / 16 times 16, renormalised near the border.
    FloatImage spike(5, 5, 4, 0.0f);
    spike.at(2, 2, 3) = 16.0f;
    auto gpu = prefilterOnGpu(spike);
    CHECK(gpu.at(2, 2) == Approx(4.0f));
    CHECK(gpu.at(1, 2) == Approx(2.0f));
    CHECK(gpu.at(1, 1) == Approx(1.0f));
    CHECK(gpu.at(0, 0) == 0.0f);
    FloatImage corner(5, 5, 4, 0.0f);
    corner.at(0, 0, 3) = 9.0f;   // corner taps: weights 4, 2, 2, 1 of 9
    CHECK(prefilterOnGpu(corner).at(0, 0) == Approx(4.0f));

    FloatImage constant(6, 4, 4, 0.25f);
    HUSH_REQUIRE_IMAGES_MATCH(prefilterOnGpu(constant), FloatImage(6, 4, 1, 0.25f), 0.0f, 1e-7f);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("svgf variance prefilter: extremes stay finite", "[svgf-atrous][svgf-prefilter]") {
    test::ValidationScope scope;
    for (float v : {0.0f, 1e-30f, 65504.0f, 1e12f, 3e38f}) {
        INFO("variance " << v);
        FloatImage illum(7, 5, 4, v);
        illum.at(3, 2, 3) = v == 0.0f ? 1e6f : 0.0f;   // a firefly / a hole
        auto gpu = prefilterOnGpu(illum);
        REQUIRE(nonFiniteCount(gpu) == 0);
        HUSH_REQUIRE_IMAGES_MATCH(gpu, reference::svgfVariancePrefilter(illum), 0.0f, 1e-6f);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
