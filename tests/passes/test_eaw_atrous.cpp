// passes/eaw/atrous: the edge-avoiding a-trous baseline of Dammertz et al. 2010
// against the CPU reference, the halving colour sigma by hand, and the filter's
// behaviour: constants stay, noise shrinks, edges hold, extremes stay finite.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <hush/passes/eaw/atrous.hpp>

#include "reference/eaw_atrous.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

// GPU (fp32, one exp of three summed exponents) vs the double reference (three
// exps): a few ulps of each exponent. Measured worst: 9.5e-7 absolute, 6.2e-7
// relative (edge scenes, one level and five chained).
constexpr float kAbsTol = 2e-6f, kRelTol = 2e-6f;

struct Scene {
    FloatImage color, normal, position;
};

// A camera-facing plane of 1 cm pixels 3 m away, 1 m further back below halfway
// (a soft edge for sigma_x = 0.5), a normal crease halfway across, scattered
// pixels without a surface (zero normal), noisy colour.
Scene edgeScene(uint32_t w, uint32_t h, uint64_t seed) {
    auto jitter = randomImage(w, h, 3, -0.05f, 0.05f, seed);
    auto noise = randomImage(w, h, 4, 0.0f, 1.0f, seed + 1);
    Scene s;
    s.normal = makeImage(w, h, 3, [&](uint32_t x, uint32_t y, uint32_t c) {
        const float base[2][3] = {{0.0f, 0.0f, 1.0f}, {0.8f, 0.0f, 0.6f}};
        return (x * 5 + y * 11) % 23 == 7 ? 0.0f : base[x >= w / 2 ? 1 : 0][c] + jitter.at(x, y, c);
    });
    s.position = makeImage(w, h, 3, [&](uint32_t x, uint32_t y, uint32_t c) {
        const float p[3] = {0.01f * float(x), -0.01f * float(y), -3.0f - (y >= h / 2 ? 1.0f : 0.0f)};
        return p[c];
    });
    s.color = makeImage(w, h, 4, [&](uint32_t x, uint32_t y, uint32_t c) {
        return c == 3 ? noise.at(x, y, 3) : (x >= w / 2 ? 1.5f : 0.5f) + 0.8f * (noise.at(x, y, c) - 0.5f);
    });
    return s;
}

// Every level of addEawAtrousLevels, read back by the transients' names.
std::vector<FloatImage> gpuLevels(const Scene& s, const passes::EawSettings& settings = {}) {
    NodeHarness t({s.color.width, s.color.height});
    auto last = passes::addEawAtrousLevels(t.ctx, "eaw", t.input("color", s.color), t.input("normal", s.normal),
                                           t.input("position", s.position), settings);
    std::vector<TextureHandle> levels;
    for (uint32_t i = 0; i < settings.iterations; ++i) {
        levels.push_back(t.graph.findTexture("eaw.level." + std::to_string(i)));
        REQUIRE(levels.back().valid());
        t.graph.markOutput(levels.back());
    }
    if (!levels.empty()) CHECK(levels.back() == last);
    return executeAndRead(t.graph, levels);
}

} // namespace

TEST_CASE("eaw a-trous: each level matches the CPU reference on inputs with edges", "[eaw]") {
    test::ValidationScope scope;
    const std::vector<uint32_t> levels = {0, 1, 2, 3, 4, 7, 40};   // 7, 40: every step beyond the image
    for (auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{3, 5}, rhi::Extent2D{64, 48}, rhi::Extent2D{257, 131}}) {
        const auto scene = edgeScene(size.width, size.height, 3);
        NodeHarness t(size);
        auto color = t.input("color", scene.color);
        auto normal = t.input("normal", scene.normal);
        auto position = t.input("position", scene.position);
        std::vector<TextureHandle> outs;
        for (uint32_t level : levels) {
            const std::string name = "level" + std::to_string(level);
            outs.push_back(passes::addEawAtrousPass(t.ctx, name, color, normal, position, level));
            t.graph.markOutput(outs.back());
        }
        t.graph.execute();
        t.graph.waitIdle();
        for (size_t i = 0; i < levels.size(); ++i) {
            INFO(size.width << "x" << size.height << " level " << levels[i]);
            auto gpu = readOutput(t.graph, outs[i]);
            auto ref = reference::eawAtrousLevel(scene.color, scene.normal, scene.position, levels[i]);
            HUSH_REQUIRE_IMAGES_MATCH(gpu, ref, kAbsTol, kRelTol);
            if (levels[i] >= 7 && size.width < 128) HUSH_REQUIRE_IMAGES_MATCH(gpu, scene.color, 0.0f, 1e-6f);
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("eaw a-trous: five chained levels match the CPU reference", "[eaw]") {
    test::ValidationScope scope;
    for (auto size : {rhi::Extent2D{3, 5}, rhi::Extent2D{61, 47}}) {
        const auto scene = edgeScene(size.width, size.height, 5);
        auto gpu = gpuLevels(scene);
        auto ref = reference::eawAtrousLevels(scene.color, scene.normal, scene.position);
        REQUIRE(gpu.size() == 5);
        for (size_t i = 0; i < gpu.size(); ++i) {
            INFO(size.width << "x" << size.height << " level " << i);
            HUSH_REQUIRE_IMAGES_MATCH(gpu[i], ref[i], kAbsTol, kRelTol);
        }
    }
    NodeHarness t({4, 4});   // no levels: the input itself
    auto color = t.input("color", FloatImage(4, 4, 4));
    CHECK(passes::addEawAtrousLevels(t.ctx, "none", color, color, color, {.iterations = 0}) == color);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("eaw a-trous: the colour sigma halves at every level, by hand", "[eaw]") {
    test::ValidationScope scope;
    CHECK(passes::eawColorSigma({.sigmaRt = 0.8f, .sigmaRtRelative = 0.0f}, 0) == 0.8f);
    CHECK(passes::eawColorSigma({.sigmaRt = 0.8f, .sigmaRtRelative = 0.0f}, 3) == 0.1f);
    CHECK(passes::eawColorSigma({.sigmaRt = 0.8f, .sigmaRtRelative = 2.0f}, 1) == 1.0f);
    CHECK(passes::eawAtrousStep(4) == 16u);
    // One row 1 + 4 * 2^level wide: the centre (colour 0) and its four taps (grey
    // 0.5, ||dc||^2 = 0.75) on one plane with one normal, so w = exp(-0.75 / sigma_i^2).
    const float sigma = 1.2f;
    for (uint32_t level = 0; level < 3; ++level) {
        const uint32_t step = 1u << level, w = 1 + 4 * step;
        FloatImage color(w, 1, 4, 0.5f), normal(w, 1, 3), position(w, 1, 3);
        for (uint32_t c = 0; c < 3; ++c) color.at(2 * step, 0, c) = 0.0f;
        for (uint32_t x = 0; x < w; ++x) normal.at(x, 0, 2) = 1.0f;
        NodeHarness t({w, 1});
        auto out = passes::addEawAtrousPass(t.ctx, "level", t.input("color", color), t.input("normal", normal),
                                            t.input("position", position), level,
                                            {.sigmaRt = sigma, .sigmaRtRelative = 0.0f});
        auto gpu = t.runOnce(out);
        const double sigmaI = sigma / double(step), wTap = std::exp(-0.75 / (sigmaI * sigmaI));
        const double expected = 0.5 * wTap * (2.0 / 16 + 2.0 / 4) / (3.0 / 8 + wTap * (2.0 / 16 + 2.0 / 4));
        INFO("level " << level << ", tap weight " << wTap);
        CHECK(gpu.at(2 * step, 0, 0) == Approx(expected).epsilon(1e-5));
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("eaw a-trous: a constant stays constant across every edge", "[eaw]") {
    test::ValidationScope scope;
    auto scene = edgeScene(40, 30, 9);
    for (uint32_t i = 0; i < 40 * 30; ++i) {
        scene.color.pixels[i * 4] = 0.37f, scene.color.pixels[i * 4 + 1] = 0.2f, scene.color.pixels[i * 4 + 2] = 0.9f;
    }
    for (const auto& level : gpuLevels(scene)) HUSH_REQUIRE_IMAGES_MATCH(level, scene.color, 0.0f, 1e-6f);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("eaw a-trous: a flat noisy region gets smoother", "[eaw]") {
    test::ValidationScope scope;
    const uint32_t n = 64;
    auto noise = randomImage(n, n, 1, -0.5f, 0.5f, 21);
    Scene s{makeImage(n, n, 4, [&](uint32_t x, uint32_t y, uint32_t) { return 1.0f + noise.at(x, y); }),
            makeImage(n, n, 3, [](uint32_t, uint32_t, uint32_t c) { return c == 2 ? 1.0f : 0.0f; }),
            makeImage(n, n, 3, [](uint32_t x, uint32_t y, uint32_t c) {
                return c == 0 ? 0.01f * float(x) : (c == 1 ? -0.01f * float(y) : -3.0f);
            })};
    auto out = gpuLevels(s).back();
    auto stats = [&](const FloatImage& img) {
        double sum = 0.0, sumSquares = 0.0;
        for (uint32_t y = 8; y < n - 8; ++y)
            for (uint32_t x = 8; x < n - 8; ++x) sum += img.at(x, y), sumSquares += double(img.at(x, y)) * img.at(x, y);
        const double count = double((n - 16) * (n - 16)), mean = sum / count;
        return std::pair{mean, sumSquares / count - mean * mean};
    };
    const auto [meanIn, varIn] = stats(s.color);
    const auto [meanOut, varOut] = stats(out);
    INFO("sample variance " << varIn << " -> " << varOut);
    CHECK(meanOut == Approx(meanIn).margin(0.02));
    CHECK(varOut < 0.25 * varIn);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("eaw a-trous: no bleeding across a position step, a normal crease or the background", "[eaw]") {
    test::ValidationScope scope;
    const uint32_t w = 48, h = 24;
    enum class Edge { None, Position, Crease, Background };
    for (Edge edge : {Edge::None, Edge::Position, Edge::Crease, Edge::Background}) {
        // Colours close enough (||dc||^2 = 0.75) for the colour term to let them blend.
        auto halves = [&](uint32_t x, uint32_t, uint32_t c) { return c == 3 ? 1.0f : (x < w / 2 ? 0.5f : 1.0f); };
        Scene s{makeImage(w, h, 4, halves), FloatImage(w, h, 3), FloatImage(w, h, 3)};
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                const bool right = x >= w / 2;
                s.normal.at(x, y, 2) = 1.0f;
                s.position.at(x, y, 0) = 0.01f * float(x), s.position.at(x, y, 1) = -0.01f * float(y);
                s.position.at(x, y, 2) = right && edge == Edge::Position ? -6.0f : -3.0f;   // exp(-36) per tap
                if (right && edge == Edge::Crease) s.normal.at(x, y, 2) = 0.0f, s.normal.at(x, y, 0) = 1.0f;
                if (right && edge == Edge::Background) s.normal.at(x, y, 2) = 0.0f;
            }
        auto out = gpuLevels(s).back();
        double worst = 0.0;
        for (uint32_t i = 0; i < w * h; ++i)
            worst = std::max(worst, std::fabs(double(out.pixels[i * 4]) - s.color.pixels[i * 4]));
        INFO("edge " << int(edge) << ": largest change " << worst);
        if (edge == Edge::None)
            CHECK(worst > 0.01);   // without an edge the two halves do blend: the test can fail
        else
            CHECK(worst < 1e-6);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("eaw a-trous: extreme values and zero sigmas stay finite and match the reference", "[eaw]") {
    test::ValidationScope scope;
    const uint32_t w = 23, h = 17;
    const auto base = edgeScene(w, h, 31);
    struct Case {
        const char* name;
        float value;
        passes::EawSettings settings;
    };
    const passes::EawSettings zeroSigmas{.sigmaRt = 0.0f, .sigmaN = 0.0f, .sigmaX = 0.0f, .sigmaRtRelative = 0.0f};
    const passes::EawSettings zeroRelative{.sigmaN = 0.0f, .sigmaX = 0.0f, .sigmaRtRelative = 1e-30f};
    for (const Case& c : {Case{"zero", 0.0f, {}}, Case{"all zero", 0.0f, {}}, Case{"tiny", 1e-30f, {}},
                          Case{"fp16 max", 65504.0f, {}}, Case{"firefly", 1e6f, {}},
                          Case{"zero sigmas", 1.0f, zeroSigmas}, Case{"zero relative sigma", 1.0f, zeroRelative},
                          Case{"zero relative sigma on black", 0.0f, zeroRelative}}) {
        auto s = base;
        const std::string name = c.name;
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                for (uint32_t ch = 0; ch < 3; ++ch) {
                    if (name == "firefly") break;
                    s.color.at(x, y, ch) = c.value * (0.5f + 0.1f * float(ch + x % 3));
                    if (name == "zero" || name == "all zero" || name == "zero relative sigma on black")
                        s.position.at(x, y, ch) = 0.0f;
                    if (name == "all zero") s.normal.at(x, y, ch) = 0.0f;   // no surface anywhere
                }
        if (name == "firefly")
            for (uint32_t ch = 0; ch < 3; ++ch) s.color.at(w / 3, h / 3, ch) = c.value;
        auto gpu = gpuLevels(s, c.settings);
        auto ref = reference::eawAtrousLevels(s.color, s.normal, s.position, c.settings);
        for (size_t i = 0; i < gpu.size(); ++i) {
            INFO(c.name << " level " << i);
            REQUIRE(nonFiniteCount(gpu[i]) == 0);
            // The firefly's relative weights divide a 1e6 difference by a local mean it
            // dominates: fp32's exp of that ratio costs one more digit (measured 2.3e-6).
            HUSH_REQUIRE_IMAGES_MATCH(gpu[i], ref[i], name == "tiny" ? 0.0f : kAbsTol, name == "firefly" ? 1e-5f : kRelTol);
        }
        if (name == "zero" || name == "all zero")
            for (uint32_t i = 0; i < w * h * 4; ++i) CHECK((i % 4 == 3 || gpu.back().pixels[i] == 0.0f));
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("eaw with a depth input compares positions relative to the centre's depth", "[eaw]") {
    test::ValidationScope scope;
    const uint32_t w = 24, h = 17;
    // The same picture at two scales (metres and millimetres): the filtered colour must match.
    auto color = randomImage(w, h, 4, 0.0f, 2.0f, 41);
    auto normal = makeImage(w, h, 3, [](uint32_t x, uint32_t, uint32_t c) { return c == 2 ? 1.0f : (x > 15 && c == 0 ? 0.2f : 0.0f); });
    auto position = makeImage(w, h, 3, [](uint32_t x, uint32_t y, uint32_t c) {
        return c == 0 ? 0.01f * float(x) : c == 1 ? 0.01f * float(y) : (x > 11 ? -3.0f : -2.0f);
    });
    auto depth = makeImage(w, h, 1, [](uint32_t x, uint32_t, uint32_t) { return x > 11 ? 3.0f : 2.0f; });
    FloatImage positionMm = position, depthMm = depth;
    for (auto& v : positionMm.pixels) v *= 1000.0f;
    for (auto& v : depthMm.pixels) v *= 1000.0f;
    passes::EawSettings s;
    for (uint32_t level : {0u, 2u}) {
        NodeHarness t({w, h});
        auto c = t.input("color", color);
        auto n = t.input("normal", normal);
        auto m = passes::addEawAtrousPass(t.ctx, "metres", c, n, t.input("position", position),
                                          t.input("depth", depth, Format::R32Float), level, s);
        auto mm = passes::addEawAtrousPass(t.ctx, "millimetres", c, n, t.input("position_mm", positionMm),
                                           t.input("depth_mm", depthMm, Format::R32Float), level, s);
        t.graph.markOutput(mm);
        const auto gpu = t.runOnce(m);
        const auto gpuMm = readOutput(t.graph, mm);
        const auto ref = reference::eawAtrousLevel(color, normal, position, level, s, &depth);
        INFO("level " << level);
        // As the other single-level comparisons.
        HUSH_REQUIRE_IMAGES_MATCH(gpu, ref, 2e-6f, 2e-6f, 3);
        HUSH_REQUIRE_IMAGES_MATCH(gpuMm, gpu, 2e-6f, 2e-6f, 3);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("eaw a-trous: the default colour weight is scale-free, the absolute one is not", "[eaw]") {
    test::ValidationScope scope;
    const uint32_t w = 29, h = 19;
    const auto scene = edgeScene(w, h, 47);
    for (const float scale : {1e-4f, 1e3f}) {
        auto scaled = scene;
        for (auto& v : scaled.color.pixels) v *= scale;
        for (const bool relative : {true, false}) {
            passes::EawSettings s;
            if (!relative) s.sigmaRtRelative = 0.0f;
            const auto base = gpuLevels(scene, s), bright = gpuLevels(scaled, s);
            const auto ref = reference::eawAtrousLevels(scaled.color, scaled.normal, scaled.position, s);
            INFO("scale " << scale << (relative ? ", relative" : ", absolute"));
            HUSH_REQUIRE_IMAGES_MATCH(bright.back(), ref.back(), kAbsTol * scale, kRelTol);
            double worst = 0.0;   // largest relative difference between scaled output and scaled input's output
            for (size_t i = 0; i < base.back().pixels.size(); i += 4)
                for (size_t c = 0; c < 3; ++c) {
                    const double a = double(base.back().pixels[i + c]) * scale, b = bright.back().pixels[i + c];
                    worst = std::max(worst, std::fabs(a - b) / std::max(std::fabs(a), 1e-30));
                }
            if (relative) CHECK(worst < 1e-4);
            else CHECK(worst > 1e-2);   // the paper's sigma is in radiance units
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
