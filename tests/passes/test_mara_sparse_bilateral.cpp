// Mara et al. 2017's sparse cross-bilateral filter (stages 4 and 7) against its CPU
// reference: the spiral tap pattern turned per pixel and frame, the Gaussian, the
// plane and normal weights, fixed and per-pixel radii.
#include <catch2/catch.hpp>

#include <cmath>

#include <hush/passes/mara/sparse_bilateral.hpp>

#include "chain_test_util.hpp"
#include "pass_test_util.hpp"
#include "reference/mara_sparse_bilateral.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

struct Guide {
    FloatImage normalDepth, position;
};

// A floor (normal +y) and a wall (normal +z) meeting at x = w / 2, and a pixel column
// without a surface; positions in world units consistent with the normals.
Guide crease(uint32_t w, uint32_t h) {
    Guide g{FloatImage(w, h, 4), FloatImage(w, h, 3)};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            if (x == 3) continue;   // no surface
            const bool wall = x >= w / 2;
            g.normalDepth.at(x, y, wall ? 2 : 1) = 1.0f;
            g.normalDepth.at(x, y, 3) = 5.0f + 0.01f * float(y);
            g.position.at(x, y, 0) = 0.05f * float(x);
            g.position.at(x, y, 1) = wall ? 0.05f * float(y) : 0.0f;
            g.position.at(x, y, 2) = wall ? 0.0f : 0.05f * float(y);
        }
    return g;
}

FloatImage gpuFilter(const FloatImage& color, const Guide& g, const FloatImage* radius,
                     const passes::MaraSparseBilateralSettings& s, uint32_t frames) {
    NodeHarness t({color.width, color.height});
    const passes::Surface surface{t.input("nd", g.normalDepth), t.input("gm", FloatImage(color.width, color.height, 4))};
    const auto r = radius ? t.input("radius", *radius, rhi::Format::R32Float) : graph::TextureHandle{};
    const auto out = passes::addMaraSparseBilateralPass(t.ctx, "bilateral", t.input("color", color), surface,
                                                        t.input("position", g.position), r, s);
    t.graph.markOutput(out);
    for (uint32_t f = 0; f + 1 < frames; ++f) t.graph.execute();
    return t.runOnce(out);
}

// Compares the pixels none of whose taps lie on a rounding boundary (see the reference).
void requireMatch(const FloatImage& gpu, const reference::MaraBilateralResult& ref) {
    FloatImage masked = ref.filtered;
    size_t ambiguous = 0;
    for (size_t i = 0; i < ref.ambiguous.size(); ++i) {
        if (!ref.ambiguous[i]) continue;
        ++ambiguous;
        for (uint32_t c = 0; c < 4; ++c) masked.pixels[i * 4 + c] = gpu.pixels[i * 4 + c];
    }
    INFO(ambiguous << " of " << ref.ambiguous.size() << " pixels have a tap on a rounding boundary");
    CHECK(ambiguous * 10 < ref.ambiguous.size());
    HUSH_REQUIRE_IMAGES_MATCH(gpu, masked, 2e-5f, 2e-5f);
}

} // namespace

TEST_CASE("mara sparse bilateral matches the CPU reference for a fixed and a per-pixel radius, frame by frame",
          "[mara][mara-sparse-bilateral]") {
    test::ValidationScope scope;
    const uint32_t w = 48, h = 31;
    const auto g = crease(w, h);
    const auto color = randomImage(w, h, 4, 0.0f, 3.0f, 21);
    const auto radius = randomImage(w, h, 1, 0.0f, 12.0f, 22);
    passes::MaraSparseBilateralSettings s;
    s.diameter = 0.25f;   // a 6-pixel radius at 48 wide: taps reach across the crease
    const reference::MaraBilateralParams p;
    for (uint32_t frames : {1u, 3u}) {
        INFO(frames << " frame(s)");
        requireMatch(gpuFilter(color, g, nullptr, s, frames),
                     reference::maraSparseBilateral(color, g.normalDepth, g.position, nullptr, 0.5 * 0.25 * w,
                                                    frames - 1, p));
        requireMatch(gpuFilter(color, g, &radius, s, frames),
                     reference::maraSparseBilateral(color, g.normalDepth, g.position, &radius, 0.0, frames - 1, p));
    }
    // The default normalPower (32) is evaluated by repeated squaring; a fractional one by pow().
    s.normalPower = 20.5f;
    reference::MaraBilateralParams fractional;
    fractional.normalPower = 20.5;
    requireMatch(gpuFilter(color, g, nullptr, s, 1),
                 reference::maraSparseBilateral(color, g.normalDepth, g.position, nullptr, 0.5 * 0.25 * w, 0, fractional));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("mara sparse bilateral: a constant stays, the crease does not bleed, the pattern turns every frame",
          "[mara][mara-sparse-bilateral]") {
    test::ValidationScope scope;
    const uint32_t w = 48, h = 31;
    const auto g = crease(w, h);
    passes::MaraSparseBilateralSettings s;
    s.diameter = 0.25f;
    // A constant.
    const auto flat = gpuFilter(FloatImage(w, h, 4, 0.75f), g, nullptr, s, 1);
    for (float v : flat.pixels) CHECK(v == Approx(0.75f).epsilon(1e-6));
    // Floor 0, wall 1: the 90 degree crease keeps them apart (n.n' = 0).
    const auto halves = makeImage(w, h, 4, [&](uint32_t x, uint32_t, uint32_t) { return x >= w / 2 ? 1.0f : 0.0f; });
    const auto split = gpuFilter(halves, g, nullptr, s, 1);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) CHECK(split.at(x, y) == halves.at(x, y));
    // The same noise filtered in frames 0 and 1 differs: the taps moved.
    const auto noise = randomImage(w, h, 4, 0.0f, 1.0f, 23);
    CHECK(relativeL1(gpuFilter(noise, g, nullptr, s, 1).pixels, gpuFilter(noise, g, nullptr, s, 2).pixels) > 0.01);
    // Every tap of the spiral stays inside the disk and none repeats another's angle.
    const reference::MaraBilateralParams p;
    for (uint32_t i = 0; i < p.taps; ++i) {
        double o[2];
        reference::maraSpiralOffset(i, p, 10.0, 0.3, o);
        CHECK(std::hypot(o[0], o[1]) <= 10.0);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
