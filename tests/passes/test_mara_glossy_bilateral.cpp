// Mara et al. 2017 stages 9 and 10: each 1D pass against its CPU reference; the blur
// widens with roughness (sigma = 7 roughness^0.1 + eps) and a mirror is left alone.
#include <catch2/catch.hpp>

#include <hush/passes/mara/glossy_bilateral.hpp>

#include "pass_test_util.hpp"
#include "reference/mara_glossy_bilateral.hpp"

using namespace hush;
using namespace hush::passes_test;

TEST_CASE("mara glossy bilateral: horizontal then vertical match the CPU reference", "[mara][mara-glossy-bilateral]") {
    test::ValidationScope scope;
    const uint32_t w = 45, h = 33;
    const auto color = randomImage(w, h, 4, 0.0f, 2.0f, 41);
    const auto roughness = makeImage(w, h, 1, [](uint32_t x, uint32_t y, uint32_t) {
        return (x + y) % 7 == 0 ? 0.0f : float((x * 3 + y) % 10) / 9.0f;
    });
    // Two planes meeting in a crease, normals and positions consistent.
    FloatImage nd(w, h, 4), position(w, h, 3);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const bool right = x > w / 2;
            nd.at(x, y, right ? 0 : 2) = 1.0f;
            nd.at(x, y, 3) = 3.0f;
            position.at(x, y, 0) = right ? 0.0f : 0.04f * float(x);
            position.at(x, y, 1) = 0.04f * float(y);
            position.at(x, y, 2) = right ? 0.04f * float(x) : 0.0f;
        }
    NodeHarness t({w, h});
    const passes::Surface surface{t.input("nd", nd), t.input("gm", FloatImage(w, h, 4))};
    const auto out = passes::addMaraGlossyBilateralPasses(t.ctx, "glossy", t.input("color", color),
                                                          t.input("roughness", roughness, rhi::Format::R32Float),
                                                          surface, t.input("position", position));
    const auto horizontal = t.graph.findTexture("glossy.horizontal");
    REQUIRE(horizontal.valid());
    t.graph.markOutput(horizontal);
    t.graph.markOutput(out);
    const auto gpu = executeAndRead(t.graph, {horizontal, out});
    const reference::MaraGlossyBilateralParams p;
    const auto refH = reference::maraGlossyBilateral(color, roughness, nd, position, false, p);
    HUSH_REQUIRE_IMAGES_MATCH(gpu[0], refH, 1e-5f, 1e-5f);
    HUSH_REQUIRE_IMAGES_MATCH(gpu[1], reference::maraGlossyBilateral(refH, roughness, nd, position, true, p), 1e-5f,
                              1e-5f);
    // A mirror pixel (roughness 0: sigma = epsilon) keeps its value.
    CHECK(gpu[1].at(0, 0, 0) == Approx(color.at(0, 0, 0)).epsilon(1e-6));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
