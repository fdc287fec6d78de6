// passes/svgf/atrous: SVGF's a-trous levels (Schied et al. 2017, Sec. 4.3-4.4)
// against the CPU reference, the variance propagation formula by hand, and the
// filter's behaviour: constants stay, noise shrinks, edges hold, extremes stay finite.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <hush/passes/svgf/atrous.hpp>
#include <hush/passes/svgf/variance_prefilter.hpp>

#include "reference/common_surface.hpp"
#include "reference/svgf_atrous.hpp"
#include "reference/svgf_variance_prefilter.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

// GPU vs the double-precision reference, one level: fp32 sums of 25 taps and the
// exp/pow of the weights (pow(cos, 128) turns the dot product's rounding into
// ~128 ulp). Measured worst on the edge scenes: 2.0e-6 absolute; 1.7e-5 relative
// on small variances (|ref| ~ 1e-3), which the absolute term covers.
constexpr float kLevelAbsTol = 1e-5f, kLevelRelTol = 1e-5f;
// Five chained levels: each level's rounding moves the next one's w_l.
// Measured: 1e-6 absolute, 1.2e-5 relative (variance channel; 65504 and 1e-30 inputs).
constexpr float kChainAbsTol = 1e-5f, kChainRelTol = 5e-5f;

struct Scene {
    FloatImage illum;   // rgb illumination, a variance
    reference::SurfaceImages surface;
};

// A sloped, slightly curved depth with a step halfway down, a normal crease
// halfway across, two mesh ids, a background rectangle and scattered background
// pixels (mesh id -1 on some, a zero normal on others), noisy illumination.
Scene edgeScene(uint32_t w, uint32_t h, uint64_t seed) {
    auto jitter = randomImage(w, h, 3, -0.05f, 0.05f, seed);
    auto normal = makeImage(w, h, 3, [&](uint32_t x, uint32_t y, uint32_t c) {
        const float base[2][3] = {{0.0f, 0.0f, 1.0f}, {0.8f, 0.0f, 0.6f}};
        const bool zero = (x * 5 + y * 11) % 23 == 7;
        return zero ? 0.0f : base[x >= w / 2 ? 1 : 0][c] + jitter.at(x, y, c);
    });
    auto depth = makeImage(w, h, 1, [&](uint32_t x, uint32_t y, uint32_t) {
        return 4.0f + 0.01f * float(x) + 0.02f * float(y) + 5e-4f * float(x * x) + (y >= h / 2 ? 2.0f : 0.0f);
    });
    auto mesh = makeImage(w, h, 1, [&](uint32_t x, uint32_t y, uint32_t) {
        const bool hole = (x >= w / 4 && x < w / 4 + w / 8 + 1 && y >= h / 4 && y < h / 4 + h / 8 + 1 && w > 4) ||
                          (x * 13 + y * 7) % 17 == 3;
        return hole ? -1.0f : (y >= h / 2 ? 2.0f : 1.0f);
    });
    auto noise = randomImage(w, h, 4, 0.0f, 1.0f, seed + 1);
    auto illum = makeImage(w, h, 4, [&](uint32_t x, uint32_t y, uint32_t c) {
        if (c == 3) return 0.1f * noise.at(x, y, 3);
        return (x >= w / 2 ? 1.5f : 0.5f) + 0.8f * (noise.at(x, y, c) - 0.5f);
    });
    return {illum, reference::surface(normal, depth, mesh)};
}

passes::Surface upload(NodeHarness& t, const reference::SurfaceImages& s) {
    return {t.input("normal_depth", s.normalDepth), t.input("gradient_mesh", s.gradientMesh)};
}

// The newest version of the transient called `name` (the node names its level
// outputs; this also checks that they carry those names).
TextureHandle transient(const graph::RenderGraph& g, const std::string& name) {
    const auto handle = g.findTexture(name);
    if (!handle.valid()) FAIL("no transient called " << name);
    return handle;
}

// The chained levels on the GPU: every level's output.
std::vector<FloatImage> gpuLevels(const FloatImage& illum, const reference::SurfaceImages& surface,
                                  const passes::SvgfAtrousSettings& s = {}) {
    NodeHarness t({illum.width, illum.height});
    passes::addSvgfAtrousLevels(t.ctx, "atrous", t.input("illum", illum), upload(t, surface), s);
    std::vector<TextureHandle> levels;
    for (uint32_t i = 0; i < s.iterations; ++i) {
        levels.push_back(transient(t.graph, "atrous.level." + std::to_string(i)));
        t.graph.markOutput(levels.back());
    }
    return executeAndRead(t.graph, levels);
}

} // namespace

TEST_CASE("svgf a-trous: each level matches the CPU reference on inputs with edges", "[svgf-atrous]") {
    test::ValidationScope scope;
    const std::vector<uint32_t> levels = {0, 1, 2, 3, 4, 7, 40};   // 7, 40: every step beyond the image
    for (auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{3, 5}, rhi::Extent2D{64, 48}, rhi::Extent2D{257, 131}}) {
        const auto scene = edgeScene(size.width, size.height, 3);
        NodeHarness t(size);
        auto illum = t.input("illum", scene.illum);
        auto prefiltered = passes::addSvgfVariancePrefilterPass(t.ctx, "prefilter", illum);
        const auto surface = upload(t, scene.surface);
        std::vector<TextureHandle> outs;
        for (uint32_t level : levels) {
            outs.push_back(passes::addSvgfAtrousPass(t.ctx, "level" + std::to_string(level), illum, prefiltered,
                                                     surface, level));
            t.graph.markOutput(outs.back());
        }
        t.runOnce(prefiltered);
        const auto refPrefiltered = reference::svgfVariancePrefilter(scene.illum);
        for (size_t i = 0; i < levels.size(); ++i) {
            INFO(size.width << "x" << size.height << " level " << levels[i]);
            auto gpu = readOutput(t.graph, outs[i]);
            auto ref = reference::svgfAtrousLevel(scene.illum, refPrefiltered, scene.surface, levels[i]);
            HUSH_REQUIRE_IMAGES_MATCH(gpu, ref, kLevelAbsTol, kLevelRelTol);
            if (levels[i] >= 7 && size.width < 128) HUSH_REQUIRE_IMAGES_MATCH(gpu, scene.illum, 0.0f, 1e-6f);
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("svgf a-trous: five chained levels match the CPU reference", "[svgf-atrous]") {
    test::ValidationScope scope;
    for (auto size : {rhi::Extent2D{3, 5}, rhi::Extent2D{61, 47}}) {
        const auto scene = edgeScene(size.width, size.height, 5);
        auto gpu = gpuLevels(scene.illum, scene.surface);
        auto ref = reference::svgfAtrousLevels(scene.illum, scene.surface);
        REQUIRE(gpu.size() == 5);
        for (size_t i = 0; i < gpu.size(); ++i) {
            INFO(size.width << "x" << size.height << " level " << i);
            HUSH_REQUIRE_IMAGES_MATCH(gpu[i], ref[i], kChainAbsTol, kChainRelTol);
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

// sigmaN = 128 (a whole number) is evaluated by repeated squaring, any other by pow():
// both against std::pow in the reference.
TEST_CASE("svgf a-trous: whole and fractional normal exponents match the CPU reference", "[svgf-atrous]") {
    test::ValidationScope scope;
    const auto scene = edgeScene(37, 23, 5);
    for (float sigmaN : {1.0f, 3.0f, 127.5f, 128.0f, 1000.0f}) {
        INFO("sigmaN " << sigmaN);
        const passes::SvgfAtrousSettings s{.sigmaN = sigmaN};
        auto gpu = gpuLevels(scene.illum, scene.surface, s);
        auto ref = reference::svgfAtrousLevels(scene.illum, scene.surface, s);
        for (size_t i = 0; i < gpu.size(); ++i) HUSH_REQUIRE_IMAGES_MATCH(gpu[i], ref[i], kChainAbsTol, kChainRelTol);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("svgf a-trous: levels are named passes and level 0 is usable as history", "[svgf-atrous]") {
    test::ValidationScope scope;
    const uint32_t w = 19, h = 13;
    const auto a = edgeScene(w, h, 7), b = edgeScene(w, h, 8);
    NodeHarness t({w, h});
    const auto surface = upload(t, a.surface);
    auto in = t.input("illum", a.illum);
    auto none = passes::addSvgfAtrousLevels(t.ctx, "none", in, surface, {.iterations = 0});
    CHECK((none.filtered == in && none.firstLevel == in));
    auto result = passes::addSvgfAtrousLevels(t.ctx, "svgf", in, surface);
    // What the temporal stage will do: read last frame's first level.
    auto last = t.graph.history(result.firstLevel);
    auto fromHistory = passes::addSvgfVariancePrefilterPass(t.ctx, "from_history", last);
    t.graph.markOutput(result.firstLevel);
    t.graph.markOutput(result.filtered);
    t.runOnce(fromHistory);
    const auto order = t.graph.passOrder();
    for (int i = 0; i < 5; ++i)
        for (const char* stage : {"prefilter", "level"})
            CHECK(std::count(order.begin(), order.end(), "svgf." + std::string(stage) + "." + std::to_string(i)) == 1);
    const auto refA = reference::svgfAtrousLevels(a.illum, a.surface);
    HUSH_REQUIRE_IMAGES_MATCH(readOutput(t.graph, result.firstLevel), refA[0], kChainAbsTol, kChainRelTol);
    HUSH_REQUIRE_IMAGES_MATCH(readOutput(t.graph, result.filtered), refA[4], kChainAbsTol, kChainRelTol);

    t.update("illum", b.illum);   // frame 2 reads frame 1's level 0 (no recompile: runOnce would mark again)
    t.graph.execute();
    t.graph.waitIdle();
    REQUIRE(t.graph.compileCount() == 1);
    auto second = readOutput(t.graph, fromHistory);
    HUSH_REQUIRE_IMAGES_MATCH(second, reference::svgfVariancePrefilter(refA[0]), kChainAbsTol, kChainRelTol);
    const auto refB = reference::svgfAtrousLevels(b.illum, a.surface);
    HUSH_REQUIRE_IMAGES_MATCH(readOutput(t.graph, result.firstLevel), refB[0], kChainAbsTol, kChainRelTol);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("svgf a-trous: variance is propagated with squared weights (Sec. 4.3)", "[svgf-atrous]") {
    test::ValidationScope scope;
    // One row, level 0: taps at x-2..x+2 with h = (1/16, 1/4, 3/8, 1/4, 1/16) (the
    // row's own 3/8 cancels). Pixel 3 is at a right angle (w_n = 0), pixel 1 sits
    // 1e-3 deeper on a plane facing the camera (w_z = exp(-dz / (1e-3 z))), all
    // luminances are equal (w_l = 1).
    const uint32_t w = 5;
    const float z0 = 2.0f, z1 = 2.002f;
    FloatImage illum(w, 1, 4), normalDepth(w, 1, 4), gradientMesh(w, 1, 4);
    const float variance[w] = {0.4f, 1.3f, 0.7f, 2.0f, 0.1f};
    for (uint32_t x = 0; x < w; ++x) {
        for (uint32_t c = 0; c < 3; ++c) illum.at(x, 0, c) = 0.6f;
        illum.at(x, 0, 3) = variance[x];
        normalDepth.at(x, 0, x == 3 ? 0 : 2) = 1.0f;
        normalDepth.at(x, 0, 3) = x == 1 ? z1 : z0;
        gradientMesh.at(x, 0, 2) = 1.0f;
    }
    NodeHarness t({w, 1});
    auto in = t.input("illum", illum);
    auto out = passes::addSvgfAtrousPass(t.ctx, "level", in, passes::addSvgfVariancePrefilterPass(t.ctx, "pre", in),
                                         {t.input("nd", normalDepth), t.input("gm", gradientMesh)}, 0);
    auto gpu = t.runOnce(out);

    const double h[w] = {1.0 / 16, 1.0 / 4, 3.0 / 8, 1.0 / 4, 1.0 / 16};
    const double weight[w] = {1.0, std::exp(-(double(z1) - double(z0)) / (1e-3 * double(z0))), 1.0, 0.0, 1.0};
    double sum = 0.0, sumSquares = 0.0;
    for (uint32_t x = 0; x < w; ++x) {
        sum += h[x] * weight[x];
        sumSquares += h[x] * h[x] * weight[x] * weight[x] * variance[x];
    }
    CHECK(weight[1] == Approx(std::exp(-1.0)).epsilon(1e-3));
    CHECK(gpu.at(2, 0, 3) == Approx(sumSquares / (sum * sum)).epsilon(1e-5));
    CHECK(gpu.at(2, 0, 0) == Approx(0.6).epsilon(1e-6));
    // Pixel 3 faces elsewhere: alone, it keeps its variance; a constant uniform
    // plane would give var * (sum h^2)^2 = var * 0.0748 in the interior.
    CHECK(gpu.at(3, 0, 3) == Approx(2.0).epsilon(1e-6));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("svgf a-trous: a constant stays constant across every edge", "[svgf-atrous]") {
    test::ValidationScope scope;
    auto scene = edgeScene(40, 30, 9);
    for (uint32_t y = 0; y < 30; ++y)
        for (uint32_t x = 0; x < 40; ++x) {
            scene.illum.at(x, y, 0) = 0.37f, scene.illum.at(x, y, 1) = 0.2f, scene.illum.at(x, y, 2) = 0.9f;
        }
    auto levels = gpuLevels(scene.illum, scene.surface);
    for (const auto& level : levels) HUSH_REQUIRE_IMAGES_MATCH(level, scene.illum, 0.0f, 1e-6f, 3);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("svgf a-trous: a flat noisy region gets smoother and its variance shrinks", "[svgf-atrous]") {
    test::ValidationScope scope;
    const uint32_t n = 64;
    auto noise = randomImage(n, n, 1, -0.5f, 0.5f, 21);
    auto illum = makeImage(n, n, 4, [&](uint32_t x, uint32_t y, uint32_t c) {
        return c == 3 ? 1.0f / 12.0f : 1.0f + noise.at(x, y);   // U(-1/2, 1/2) has variance 1/12
    });
    auto surface = reference::surface(FloatImage(n, n, 3, 0.0f), FloatImage(n, n, 1, 3.0f), FloatImage(n, n, 1, 0.0f));
    for (uint32_t i = 0; i < n * n; ++i) surface.normalDepth.pixels[i * 4 + 2] = 1.0f;
    auto out = gpuLevels(illum, surface).back();
    auto stats = [&](const FloatImage& img, uint32_t c) {
        double sum = 0.0, sumSquares = 0.0;
        for (uint32_t y = 8; y < n - 8; ++y)
            for (uint32_t x = 8; x < n - 8; ++x) {
                sum += img.at(x, y, c);
                sumSquares += double(img.at(x, y, c)) * img.at(x, y, c);
            }
        const double count = double((n - 16) * (n - 16)), mean = sum / count;
        return std::pair{mean, sumSquares / count - mean * mean};
    };
    const auto [meanIn, varIn] = stats(illum, 0);
    const auto [meanOut, varOut] = stats(out, 0);
    const auto [propagated, unused] = stats(out, 3);
    INFO("sample variance " << varIn << " -> " << varOut << ", propagated " << propagated);
    CHECK(meanOut == Approx(meanIn).margin(0.02));
    CHECK(varOut < 0.1 * varIn);
    CHECK(propagated < 0.1 / 12.0);
    CHECK(propagated > 0.0);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("svgf a-trous: no bleeding across a depth step, a normal crease or the background", "[svgf-atrous]") {
    test::ValidationScope scope;
    const uint32_t w = 48, h = 24;
    enum class Edge { None, Depth, Crease, Background };
    for (Edge edge : {Edge::None, Edge::Depth, Edge::Crease, Edge::Background}) {
        FloatImage normal(w, h, 3), depth(w, h, 1, 2.0f), mesh(w, h, 1, 1.0f);
        auto illum = makeImage(w, h, 4, [&](uint32_t x, uint32_t, uint32_t c) {
            return c == 3 ? 0.5f : (x < w / 2 ? 0.1f : 4.0f);   // a variance that lets w_l blend
        });
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                const bool right = x >= w / 2;
                normal.at(x, y, 2) = 1.0f;
                if (right && edge == Edge::Depth) depth.at(x, y) = 6.0f;
                if (right && edge == Edge::Crease) normal.at(x, y, 2) = 0.0f, normal.at(x, y, 0) = 1.0f;
                if (right && edge == Edge::Background) mesh.at(x, y) = -1.0f;
            }
        auto out = gpuLevels(illum, reference::surface(normal, depth, mesh)).back();
        double worst = 0.0;
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                worst = std::max(worst, std::fabs(double(out.at(x, y, 0)) - illum.at(x, y, 0)));
        INFO("edge " << int(edge) << ": largest change " << worst);
        if (edge == Edge::None)
            CHECK(worst > 0.1);   // without an edge the two halves do blend: the test can fail
        else
            CHECK(worst < 1e-6);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("svgf a-trous: extreme values stay finite and match the reference", "[svgf-atrous]") {
    test::ValidationScope scope;
    const uint32_t w = 23, h = 17;
    auto base = edgeScene(w, h, 31);
    struct Case {
        const char* name;
        float colour, variance;
    };
    for (const Case& c : {Case{"zero", 0.0f, 0.0f}, Case{"tiny", 1e-30f, 1e-30f}, Case{"fp16 max", 65504.0f, 65504.0f},
                          Case{"firefly", 1e6f, 1e12f}}) {
        auto illum = base.illum;
        auto surface = base.surface;
        const bool firefly = std::string(c.name) == "firefly";
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                for (uint32_t ch = 0; ch < 4; ++ch)
                    if (!firefly)
                        illum.at(x, y, ch) = ch == 3 ? c.variance : c.colour * (0.5f + 0.1f * float(ch + x % 3));
        if (firefly) {
            for (uint32_t ch = 0; ch < 3; ++ch) illum.at(w / 3, h / 3, ch) = c.colour;
            illum.at(w / 3, h / 3, 3) = c.variance;
        }
        if (std::string(c.name) == "zero") {   // and a degenerate surface: depth and slopes 0
            for (uint32_t i = 0; i < w * h; ++i) {
                surface.normalDepth.pixels[i * 4 + 3] = 0.0f;
                surface.gradientMesh.pixels[i * 4] = surface.gradientMesh.pixels[i * 4 + 1] = 0.0f;
            }
        }
        auto gpu = gpuLevels(illum, surface);
        auto ref = reference::svgfAtrousLevels(illum, surface);
        for (size_t i = 0; i < gpu.size(); ++i) {
            INFO(c.name << " level " << i);
            REQUIRE(nonFiniteCount(gpu[i]) == 0);
            // 1e-30: no absolute slack, or every value would pass.
            HUSH_REQUIRE_IMAGES_MATCH(gpu[i], ref[i], c.colour == 1e-30f ? 0.0f : kChainAbsTol, kChainRelTol);
        }
        if (std::string(c.name) == "zero")
            for (float v : gpu.back().pixels) CHECK(v == 0.0f);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
