// Mara et al. 2017 stage 5: two 1D min passes give the minimum over the whole
// (2R+1) x (2R+1) box (checked against brute force), and the radius grows where the
// confidence is low, six times where the pixel's own is below 1/2.
#include <catch2/catch.hpp>

#include <hush/passes/mara/disocclusion.hpp>

#include "pass_test_util.hpp"
#include "reference/mara_disocclusion.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {
FloatImage gpuRadius(const FloatImage& temporal, const passes::MaraDisocclusionSettings& s = {}) {
    NodeHarness t({temporal.width, temporal.height});
    return t.runOnce(passes::addMaraDisocclusionPass(t.ctx, "disocclusion", t.input("temporal", temporal), s));
}
} // namespace

TEST_CASE("mara disocclusion: the separable minimum equals the brute-force box minimum", "[mara][mara-disocclusion]") {
    test::ValidationScope scope;
    for (auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{7, 3}, rhi::Extent2D{61, 40}, rhi::Extent2D{200, 9}}) {
        INFO(size.width << "x" << size.height);
        // Mostly confident (0.98), with holes of every depth.
        auto temporal = makeImage(size.width, size.height, 4, [](uint32_t x, uint32_t y, uint32_t c) {
            if (c < 3) return 0.0f;
            const uint32_t k = (x * 31 + y * 17) % 23;
            return k == 0 ? 0.0f : k == 1 ? 0.3f : k == 2 ? 0.6f : 0.98f;
        });
        const passes::MaraDisocclusionSettings s;
        const int R = passes::maraDisocclusionBoxRadius(s, size.width);
        HUSH_REQUIRE_IMAGES_MATCH(gpuRadius(temporal, s), reference::maraDisocclusion(temporal, R, 0.5, 6.0), 1e-6f,
                                  1e-6f);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

// The shaders filter runs of 8 pixels that share their windows' core (mara/window_min.glsl),
// or each window alone where 2R + 1 < 8: radii on both sides of that, up to the whole
// width, on random confidences and sizes that leave partial runs along both axes.
TEST_CASE("mara disocclusion: every radius from 1 to the width equals the brute-force box minimum",
          "[mara][mara-disocclusion]") {
    test::ValidationScope scope;
    const uint32_t w = 61, h = 45;
    const auto temporal = randomImage(w, h, 4, 0.0f, 1.0f, 81);
    for (int R : {1, 3, 4, 7, 8, 30, 61}) {
        INFO("R " << R);
        passes::MaraDisocclusionSettings s;
        s.maxRadius = float(R) / float(w);
        REQUIRE(passes::maraDisocclusionBoxRadius(s, w) == R);
        HUSH_REQUIRE_IMAGES_MATCH(gpuRadius(temporal, s), reference::maraDisocclusion(temporal, R, 0.5, 6.0), 1e-6f,
                                  1e-6f);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("mara disocclusion: R is a twentieth of the width; a hole widens the radius around it",
          "[mara][mara-disocclusion]") {
    test::ValidationScope scope;
    const uint32_t w = 100, h = 20;   // R = 5
    CHECK(passes::maraDisocclusionBoxRadius({}, w) == 5);
    auto temporal = FloatImage(w, h, 4, 0.98f);
    temporal.at(50, 10, 3) = 0.0f;   // one disoccluded pixel
    const auto r = gpuRadius(temporal);
    CHECK(r.at(50, 10) == Approx(5.0f * 6.0f));          // (1 - 0) R, times 6: c < 1/2 here
    CHECK(r.at(55, 15) == Approx(5.0f));                 // in its box: (1 - 0) R
    CHECK(r.at(56, 10) == Approx(0.02f * 5.0f));         // outside: (1 - 0.98) R
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
