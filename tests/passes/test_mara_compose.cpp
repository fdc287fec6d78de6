// Mara et al. 2017's composite against its CPU reference: direct + (1 - F)^2 albedo
// matte + F glossy with Schlick's F towards the camera; no coat, no Fresnel; without
// the glossy term, none of it.
#include <catch2/catch.hpp>

#include <hush/passes/mara/compose.hpp>

#include "pass_test_util.hpp"
#include "reference/mara_compose.hpp"

using namespace hush;
using namespace hush::passes_test;

TEST_CASE("mara compose matches the CPU reference with and without the glossy term", "[mara][mara-compose]") {
    test::ValidationScope scope;
    const uint32_t w = 29, h = 17;
    const auto direct = randomImage(w, h, 3, 0.0f, 2.0f, 51);
    const auto matte = randomImage(w, h, 3, 0.0f, 2.0f, 52);
    const auto glossy = randomImage(w, h, 3, 0.0f, 2.0f, 53);
    const auto albedo = randomImage(w, h, 3, 0.0f, 1.0f, 54);
    // F0 0 (no coat) on every third pixel, else dielectric to metal.
    const auto specular = makeImage(w, h, 3, [](uint32_t x, uint32_t y, uint32_t c) {
        return (x + y) % 3 == 0 ? 0.0f : 0.04f + 0.3f * float((x + c) % 4);
    });
    // Normals facing the camera at every angle, and a column without a surface.
    FloatImage nd(w, h, 4), position(w, h, 3);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            if (x == 5) continue;
            const float a = 1.5f * float(y) / float(h);
            nd.at(x, y, 0) = std::sin(a);
            nd.at(x, y, 2) = std::cos(a);
            nd.at(x, y, 3) = 2.0f;
            position.at(x, y, 0) = 0.1f * float(x);
            position.at(x, y, 2) = -2.0f;
        }
    auto camera = std::make_shared<passes::FrameCamera>();
    camera->position = {1.0f, 0.5f, 1.0f};
    for (bool withGlossy : {true, false}) {
        INFO("glossy " << withGlossy);
        NodeHarness t({w, h});
        passes::MaraComposeInputs in{.direct = t.input("direct", direct),
                                     .matte = t.input("matte", matte),
                                     .glossy = withGlossy ? t.input("glossy", glossy) : graph::TextureHandle{},
                                     .albedo = t.input("albedo", albedo),
                                     .specular = t.input("specular", specular),
                                     .surface = {t.input("nd", nd), t.input("gm", FloatImage(w, h, 4))},
                                     .position = t.input("position", position)};
        const auto gpu = t.runOnce(passes::addMaraComposePass(t.ctx, "compose", in, camera));
        const auto ref = reference::maraCompose(direct, matte, withGlossy ? &glossy : nullptr, albedo, specular, nd,
                                                position, {1.0, 0.5, 1.0});
        HUSH_REQUIRE_IMAGES_MATCH(gpu, ref, 1e-5f, 1e-5f, 3);
        // Without a surface: the direct light alone.
        CHECK(gpu.at(5, 3, 0) == direct.at(5, 3, 0));
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
