// Mara et al. 2017 stage 6: the per-channel 3x3 median against sorting on the CPU; a
// lone firefly disappears, a one-pixel line of them too, an edge stays.
#include <catch2/catch.hpp>

#include <hush/passes/mara/median.hpp>

#include "pass_test_util.hpp"
#include "reference/mara_median.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {
FloatImage gpuMedian(const FloatImage& color) {
    NodeHarness t({color.width, color.height});
    return t.runOnce(passes::addMaraMedianPass(t.ctx, "median", t.input("color", color)));
}
} // namespace

TEST_CASE("mara median matches sorting, per channel, with repeated edges", "[mara][mara-median]") {
    test::ValidationScope scope;
    for (auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{2, 5}, rhi::Extent2D{37, 29}}) {
        INFO(size.width << "x" << size.height);
        const auto color = randomImage(size.width, size.height, 4, -2.0f, 5.0f, 31);
        HUSH_REQUIRE_IMAGES_MATCH(gpuMedian(color), reference::maraMedian(color), 0.0f, 0.0f, 3);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("mara median removes a 1e6 firefly and keeps an edge", "[mara][mara-median]") {
    test::ValidationScope scope;
    auto color = makeImage(16, 16, 4, [](uint32_t x, uint32_t, uint32_t) { return x < 8 ? 0.25f : 1.0f; });
    color.at(4, 4, 0) = color.at(4, 4, 1) = color.at(4, 4, 2) = 1e6f;
    const auto out = gpuMedian(color);
    for (uint32_t y = 0; y < 16; ++y)
        for (uint32_t x = 0; x < 16; ++x) CHECK(out.at(x, y, 0) == (x < 8 ? 0.25f : 1.0f));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
