// passes/common/tile_list: the nodes that split a rare, costly case into listed tiles
// (common/reproject's 3x3 fallback, svgf/variance_estimate's 7x7 estimate) list
// exactly the tiles where some pixel needs it, reset the list every frame, and give
// the CPU reference's output in the listed tiles and the others alike; the decision's
// consumers (svgf temporal, bmfr accumulate) read 3x3 footprints in its listed tiles.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

#include <hush/passes/bmfr/accumulate.hpp>
#include <hush/passes/common/reproject.hpp>
#include <hush/passes/common/tile_list.hpp>
#include <hush/passes/svgf/temporal_accumulation.hpp>
#include <hush/passes/svgf/variance_estimate.hpp>

#include "reference/bmfr_accumulate.hpp"
#include "reference/common_reproject.hpp"
#include "reference/common_surface.hpp"
#include "reference/svgf_temporal_accumulation.hpp"
#include "reference/svgf_variance_estimate.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

// The node's tile list "<name>", marked as an output (before the first frame) so
// that the test can read what the classifying pass left in it.
graph::BufferHandle exposeTileList(graph::RenderGraph& graph, const std::string& name) {
    const graph::BufferHandle list = graph.findBuffer(name);
    REQUIRE(list.valid());
    graph.markOutput(list);
    return list;
}

// The listed tiles' indices, after checking the list's layout: counts (n, 1, 1), a
// flag set exactly for each listed tile, each listed once.
std::set<uint32_t> listedTiles(const graph::RenderGraph& graph, graph::BufferHandle list, rhi::Extent2D size,
                               rhi::Extent2D tile) {
    const auto words = readOutputBuffer(graph, list);
    REQUIRE(words.size() == passes::tileListWords(size, tile));
    const uint32_t tiles = uint32_t(words.size() - 4) / 2;
    REQUIRE(words[0] <= tiles);
    CHECK(words[1] == 1);
    CHECK(words[2] == 1);
    std::set<uint32_t> listed(words.begin() + 4 + tiles, words.begin() + 4 + tiles + words[0]);
    CHECK(listed.size() == words[0]);
    for (uint32_t t = 0; t < tiles; ++t) CHECK(words[4 + t] == (listed.count(t) ? 1u : 0u));
    return listed;
}

reference::SurfaceImages wallWithBox(uint32_t w, uint32_t h, int boxLeft) {
    reference::SurfaceImages s{FloatImage(w, h, 4), FloatImage(w, h, 4)};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const bool box = int(x) >= boxLeft && int(x) < boxLeft + 6 && y >= 10 && y <= 15;
            s.normalDepth.at(x, y, 2) = 1.0f;
            s.normalDepth.at(x, y, 3) = box ? 2.0f : 5.0f;
            s.gradientMesh.at(x, y, 2) = box ? 2.0f : 1.0f;
        }
    return s;
}

// 40x20 in 8x8 tiles (5 x 3). A box (mesh 2) over a wall (mesh 1) moves 2 pixels
// right, from x [18, 24) to [20, 26), rows 10..15: the revealed wall at x 18..19
// fails its 2x2 taps, all in tile (2, 1) = index 7. Its inputs, imported.
constexpr uint32_t kBoxW = 40, kBoxH = 20;
struct MovingBox {
    reference::SurfaceImages prev = wallWithBox(kBoxW, kBoxH, 18), cur = wallWithBox(kBoxW, kBoxH, 20);
    FloatImage motion = makeImage(kBoxW, kBoxH, 2, [](uint32_t x, uint32_t y, uint32_t c) {
        return c == 0 && x >= 20 && x < 26 && y >= 10 && y <= 15 ? -2.0f : 0.0f;
    });
    NodeHarness t{{kBoxW, kBoxH}};
    graph::TextureHandle reproject() {
        auto mv = t.input("motion", motion, rhi::Format::RG32Float);
        const passes::Surface current{t.input("cur.nd", cur.normalDepth), t.input("cur.gm", cur.gradientMesh)};
        const passes::Surface previous{t.input("prev.nd", prev.normalDepth), t.input("prev.gm", prev.gradientMesh)};
        return passes::addReprojectPass(t.ctx, "reproject", mv, current, previous);
    }
};

} // namespace

TEST_CASE("tile list: reproject lists the one tile where the 3x3 fallback is needed, and none once still",
          "[reproject][tile-list]") {
    test::ValidationScope scope;
    // MovingBox: tile 7 needs the fallback.
    const uint32_t w = kBoxW, h = kBoxH;
    const rhi::Extent2D tile{8, 8};
    MovingBox box;
    auto& t = box.t;
    const auto &prev = box.prev, &cur = box.cur;
    const auto& motion = box.motion;
    auto decision = box.reproject();
    const auto list = exposeTileList(t.graph, "reproject.tiles");

    t.runOnce(decision);   // history invalid: every pixel disoccluded, nothing listed
    CHECK(listedTiles(t.graph, list, {w, h}, tile).empty());
    t.graph.execute();
    t.graph.waitIdle();
    HUSH_REQUIRE_IMAGES_MATCH(readOutput(t.graph, decision), reference::reproject(motion, cur, prev, {}, true), 1e-5f,
                              1e-6f);
    CHECK(listedTiles(t.graph, list, {w, h}, tile) == std::set<uint32_t>{7});
    CHECK(readOutput(t.graph, decision).at(18, 12, 3) == float(passes::ReprojectionMode::Fallback3x3));

    // The box stops: no pixel needs the fallback, and last frame's tile is not listed.
    t.update("prev.nd", cur.normalDepth);
    t.update("prev.gm", cur.gradientMesh);
    t.update("motion", FloatImage(w, h, 2));
    t.graph.execute();
    t.graph.waitIdle();
    HUSH_REQUIRE_IMAGES_MATCH(readOutput(t.graph, decision), reference::reproject(FloatImage(w, h, 2), cur, cur, {}, true),
                              1e-5f, 1e-6f);
    CHECK(listedTiles(t.graph, list, {w, h}, tile).empty());
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

namespace {

// A tilted plane (depth 2 + x / 10), mesh 1, with no surface where `background`.
reference::SurfaceImages plane(uint32_t w, uint32_t h, const std::set<std::pair<uint32_t, uint32_t>>& background) {
    reference::SurfaceImages s{FloatImage(w, h, 4), FloatImage(w, h, 4)};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const bool none = background.count({x, y}) > 0;
            s.normalDepth.at(x, y, 2) = none ? 0.0f : 1.0f;
            s.normalDepth.at(x, y, 3) = 2.0f + 0.1f * float(x);
            s.gradientMesh.at(x, y, 0) = 0.1f;
            s.gradientMesh.at(x, y, 2) = none ? -1.0f : 1.0f;
        }
    return s;
}

// Random colour and moments, history 9 except at `shortPixels` (history 2).
reference::SvgfTemporalImages moments(uint32_t w, uint32_t h, const std::set<std::pair<uint32_t, uint32_t>>& shortPixels,
                                      uint64_t seed) {
    reference::SvgfTemporalImages m{randomImage(w, h, 4, 0.0f, 2.0f, seed), randomImage(w, h, 4, 0.0f, 2.0f, seed + 1)};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            m.moments.at(x, y, 1) += m.moments.at(x, y, 0) * m.moments.at(x, y, 0);   // mu2 >= mu1^2
            m.moments.at(x, y, 2) = shortPixels.count({x, y}) ? 2.0f : 9.0f;
        }
    return m;
}

} // namespace

TEST_CASE("tile list: svgf variance lists the tiles with a short history on a surface, frame by frame",
          "[svgf-variance][tile-list]") {
    test::ValidationScope scope;
    // 70x37 in tiles of 32x8 (3 x 5). Frame 1: short histories at (5, 3) in tile 0 and
    // (65, 36) in the corner tile 14, and at (40, 12) in tile 4, where there is no
    // surface: no neighbour weighs there, so it is estimated without listing. Frame 2:
    // one short history at (33, 9), tile 4.
    const uint32_t w = 70, h = 37;
    const rhi::Extent2D tile{32, 8};
    const auto surface = plane(w, h, {{40, 12}, {41, 12}});
    const auto first = moments(w, h, {{5, 3}, {65, 36}, {40, 12}}, 7);
    const auto second = moments(w, h, {{33, 9}}, 9);
    for (const passes::SvgfVarianceSettings& settings :
         {passes::SvgfVarianceSettings{}, passes::SvgfVarianceSettings{.sigmaN = 0.0f}}) {
        // sigmaN = 0 makes w_n = 1 whatever the normals: then a pixel without a surface
        // has neighbours that weigh, and its tile is listed.
        INFO("sigmaN " << settings.sigmaN);
        NodeHarness t({w, h});
        const passes::SvgfTemporal temporal{t.input("color", first.color), t.input("moments", first.moments)};
        const passes::Surface s{t.input("nd", surface.normalDepth), t.input("gm", surface.gradientMesh)};
        auto variance = passes::addSvgfVariancePass(t.ctx, "variance", temporal, s, settings);
        const auto list = exposeTileList(t.graph, "variance.tiles");

        const auto gpu1 = t.runOnce(variance);
        HUSH_REQUIRE_IMAGES_MATCH(gpu1, reference::svgfVariance(first, surface, settings), 1e-5f, 1e-4f);
        const std::set<uint32_t> firstTiles = settings.sigmaN > 0.0f ? std::set<uint32_t>{0, 14}
                                                                      : std::set<uint32_t>{0, 4, 14};
        CHECK(listedTiles(t.graph, list, {w, h}, tile) == firstTiles);

        t.update("color", second.color);
        t.update("moments", second.moments);
        t.graph.execute();
        t.graph.waitIdle();
        HUSH_REQUIRE_IMAGES_MATCH(readOutput(t.graph, variance), reference::svgfVariance(second, surface, settings),
                                  1e-5f, 1e-4f);
        CHECK(listedTiles(t.graph, list, {w, h}, tile) == std::set<uint32_t>{4});
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("tile list: svgf temporal and bmfr accumulate read 3x3 footprints in the reprojection's listed tiles",
          "[svgf-temporal][bmfr-accumulate][tile-list]") {
    test::ValidationScope scope;
    // The moving box of the reprojection case above, three frames: the first without
    // history, then twice the same motion, so that the third frame's 3x3 footprints
    // (x = 18) read what the second frame's listed passes wrote.
    const uint32_t w = kBoxW, h = kBoxH;
    MovingBox box;
    auto& t = box.t;
    auto illumination = t.input("illumination", FloatImage(w, h, 4));
    auto decision = box.reproject();
    REQUIRE(passes::reprojectionFallbackTiles(t.graph, decision).valid());
    const auto temporal = passes::addSvgfTemporalPass(t.ctx, "temporal", illumination, decision);
    const auto accumulated = passes::addBmfrAccumulatePass(t.ctx, "accumulate", illumination, decision);
    for (auto out : {decision, temporal.color, temporal.moments, accumulated}) t.graph.markOutput(out);
    t.graph.compile();
    const auto names = t.graph.passOrder();
    CHECK(std::count(names.begin(), names.end(), "temporal.fallback") == 1);
    CHECK(std::count(names.begin(), names.end(), "accumulate.fallback") == 1);

    reference::SvgfTemporalImages svgfRef{FloatImage(w, h, 4), FloatImage(w, h, 4)};
    FloatImage bmfrRef(w, h, 4);
    std::vector<int> fallbackPixels;
    for (int frame = 0; frame < 3; ++frame) {
        INFO("frame " << frame);
        const auto illum = randomImage(w, h, 4, 0.0f, 3.0f, 40 + frame);
        t.update("illumination", illum);
        t.graph.execute();
        t.graph.waitIdle();
        const auto d = readOutput(t.graph, decision);
        const bool valid = frame > 0;
        svgfRef = reference::svgfTemporal(illum, d, svgfRef, {}, valid);
        bmfrRef = reference::bmfrAccumulate(illum, d, bmfrRef, {}, valid);
        HUSH_REQUIRE_IMAGES_MATCH(readOutput(t.graph, temporal.color), svgfRef.color, 1e-5f, 1e-5f);
        HUSH_REQUIRE_IMAGES_MATCH(readOutput(t.graph, temporal.moments), svgfRef.moments, 1e-5f, 1e-5f);
        HUSH_REQUIRE_IMAGES_MATCH(readOutput(t.graph, accumulated), bmfrRef, 1e-5f, 1e-5f);
        fallbackPixels.push_back(0);
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                fallbackPixels.back() += d.at(x, y, 3) == float(passes::ReprojectionMode::Fallback3x3) ? 1 : 0;
    }
    // The wall revealed at x = 18 reads 3x3 footprints in frames 1 and 2.
    CHECK(fallbackPixels[0] == 0);
    CHECK(fallbackPixels[1] > 0);
    CHECK(fallbackPixels[2] == fallbackPixels[1]);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("tile list: a decision not made by addReprojectPass has no tile list, and its consumer is one pass",
          "[svgf-temporal][tile-list]") {
    test::ValidationScope scope;
    NodeHarness t({16, 8});
    auto decision = t.input("decision", reference::identityDecision(16, 8));
    CHECK_FALSE(passes::reprojectionFallbackTiles(t.graph, decision).valid());
    const auto temporal = passes::addSvgfTemporalPass(t.ctx, "temporal", t.input("illumination", FloatImage(16, 8, 4)),
                                                      decision);
    t.runOnce(temporal.color);
    CHECK(t.graph.passOrder() == std::vector<std::string>{"temporal"});
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
