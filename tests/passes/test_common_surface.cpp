// passes/common/surface: G-buffer packing and the depth gradient, against the CPU reference.
#include <catch2/catch.hpp>

#include <hush/passes/common/surface.hpp>

#include "reference/common_surface.hpp"

using namespace hush;
using namespace hush::passes_test;

TEST_CASE("surface packs normal and depth and takes the smaller one-sided depth slope", "[common][surface]") {
    test::ValidationScope scope;
    for (auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{3, 5}, rhi::Extent2D{29, 17}}) {
        const uint32_t w = size.width, h = size.height;
        auto normal = randomImage(w, h, 3, -1.0f, 1.0f, 11);
        normal.at(0, 0, 0) = normal.at(0, 0, 1) = normal.at(0, 0, 2) = 0.0f;   // no surface
        // A tilted plane with a step: slopes must ignore the step on either side.
        auto depth = makeImage(w, h, 1, [](uint32_t x, uint32_t y, uint32_t) {
            return 2.0f + 0.25f * float(x) + 0.5f * float(y) + (x >= 10 ? 30.0f : 0.0f);
        });
        auto mesh = makeImage(w, h, 1, [](uint32_t x, uint32_t, uint32_t) { return x >= 10 ? 3.0f : 1.0f; });
        mesh.at(w - 1, h - 1) = -1.0f;   // no surface by its mesh id, whatever its normal

        NodeHarness t(size);
        auto s = passes::addSurfacePass(t.ctx, "surface", t.input("normal", normal),
                                        t.input("depth", depth, rhi::Format::R32Float),
                                        t.input("meshid", mesh, rhi::Format::R32Float));
        t.graph.markOutput(s.gradientMesh);
        auto nd = t.runOnce(s.normalDepth);
        auto gm = readOutput(t.graph, s.gradientMesh);
        auto ref = reference::surface(normal, depth, mesh);
        INFO(w << "x" << h);
        HUSH_REQUIRE_IMAGES_MATCH(nd, ref.normalDepth, 1e-6f, 1e-6f);
        HUSH_REQUIRE_IMAGES_MATCH(gm, ref.gradientMesh, 1e-6f, 1e-6f);
        // "No surface" has one encoding: a zero normal, the depth kept.
        for (uint32_t c = 0; c < 3; ++c) CHECK(nd.at(w - 1, h - 1, c) == 0.0f);
        CHECK(nd.at(w - 1, h - 1, 3) == depth.at(w - 1, h - 1));
        if (w > 11) {
            CHECK(gm.at(10, 0, 0) == Approx(0.25f));   // beside the step on its right
            CHECK(gm.at(9, 0, 0) == Approx(0.25f));    // and on its left
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("surface slope ignores neighbours on other meshes: a one-pixel blade against the sky has slope 0",
          "[common][surface]") {
    test::ValidationScope scope;
    const uint32_t w = 11, h = 4;
    auto normal = makeImage(w, h, 3, [](uint32_t, uint32_t, uint32_t c) { return c == 2 ? 1.0f : 0.0f; });
    // Column 5 is a blade (mesh 2, depth 1); the rest is sky (mesh -1, the far plane).
    auto depth = makeImage(w, h, 1, [](uint32_t x, uint32_t, uint32_t) { return x == 5 ? 1.0f : 1000.0f; });
    auto mesh = makeImage(w, h, 1, [](uint32_t x, uint32_t, uint32_t) { return x == 5 ? 2.0f : -1.0f; });
    NodeHarness t({w, h});
    auto s = passes::addSurfacePass(t.ctx, "surface", t.input("normal", normal),
                                    t.input("depth", depth, rhi::Format::R32Float),
                                    t.input("meshid", mesh, rhi::Format::R32Float));
    auto gm = t.runOnce(s.gradientMesh);
    HUSH_REQUIRE_IMAGES_MATCH(gm, reference::surface(normal, depth, mesh).gradientMesh, 1e-6f, 1e-6f);
    CHECK(gm.at(5, 1, 0) == 0.0f);   // was 999 before: every depth test would pass
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
