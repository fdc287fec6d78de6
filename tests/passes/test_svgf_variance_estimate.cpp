// svgf/variance_estimate (Schied et al. 2017 Sec. 4.2): against the CPU reference on
// both branches (temporal moments; 7x7 bilateral where the history is short), the
// variance of known sample sequences through the temporal pass, and extremes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <hush/passes/svgf/temporal_accumulation.hpp>
#include <hush/passes/svgf/variance_estimate.hpp>

#include "reference/common_reproject.hpp"
#include "reference/common_surface.hpp"
#include "reference/svgf_temporal_accumulation.hpp"
#include "reference/svgf_variance_estimate.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

FloatImage runVariance(const reference::SvgfTemporalImages& in, const reference::SurfaceImages& s,
                       const passes::SvgfVarianceSettings& settings = {}) {
    NodeHarness t({in.color.width, in.color.height});
    const passes::SvgfTemporal temporal{t.input("color", in.color), t.input("moments", in.moments)};
    const passes::Surface surface{t.input("nd", s.normalDepth), t.input("gm", s.gradientMesh)};
    return t.runOnce(passes::addSvgfVariancePass(t.ctx, "variance", temporal, surface, settings));
}

// A tilted plane with a depth step at x = 9, normals tilted a little at random (so
// w_n = (n.n')^128 spans (0, 1]), a turned face below y = 3 of a wider image, and
// background (no normal, mesh -1) in the top row.
reference::SurfaceImages testSurface(uint32_t w, uint32_t h) {
    reference::SurfaceImages s{FloatImage(w, h, 4), FloatImage(w, h, 4)};
    auto tilt = randomImage(w, h, 2, -0.08f, 0.08f, 31);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const bool background = y == 0 && h > 1;
            float n[3] = {tilt.at(x, y, 0) + (y >= 3 && w > 9 ? 0.6f : 0.0f), tilt.at(x, y, 1), 1.0f};
            const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (uint32_t c = 0; c < 3; ++c) s.normalDepth.at(x, y, c) = background ? 0.0f : n[c] / len;
            s.normalDepth.at(x, y, 3) = 2.0f + 0.1f * float(x) + 0.05f * float(y) + (x >= 9 ? 3.0f : 0.0f);
            s.gradientMesh.at(x, y, 0) = 0.1f;
            s.gradientMesh.at(x, y, 1) = 0.05f;
            s.gradientMesh.at(x, y, 2) = background ? -1.0f : 1.0f;
        }
    return s;
}

// Integrated colour and moments with history lengths 1, 2, 3, 4, 9 in turn; mu2
// mostly above mu1^2, and below it (clamped to variance 0) every seventh pixel.
reference::SvgfTemporalImages testTemporal(uint32_t w, uint32_t h, float scale, uint64_t seed) {
    reference::SvgfTemporalImages t{randomImage(w, h, 4, 0.0f, scale, seed), FloatImage(w, h, 4)};
    test::Lcg lcg(seed + 1);
    const float lengths[5] = {1, 2, 3, 4, 9};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const float mu1 = lcg.uniform(0.0f, scale);
            const float var = lcg.uniform(0.0f, scale * scale * 0.5f);
            t.moments.at(x, y, 0) = mu1;
            t.moments.at(x, y, 1) = (x + y) % 7 == 0 ? 0.5f * mu1 * mu1 : mu1 * mu1 + var;
            t.moments.at(x, y, 2) = lengths[(x + 2 * y) % 5];
        }
    return t;
}

// fp32 on the GPU (exp, pow of the weights, mu2 - mu1^2) against fp64 on the CPU.
// Colour: 1e-5 relative. Variance: 1e-4 relative + 3e-5 of the squared scale, as
// mu2 - mu1^2 cancels a few ulps of mu2 ~ scale^2 and the short-history boost can
// multiply that by up to minHistoryLength (10 in one case). Measured worst: 9.5e-6
// of scale^2 (that boosted case), 1.7e-6 relative on colour.
void requireVarianceMatch(const FloatImage& gpu, const FloatImage& ref, float scale) {
    REQUIRE(nonFiniteCount(gpu) == 0);
    HUSH_REQUIRE_IMAGES_MATCH(gpu, ref, 1e-6f * scale, 1e-5f, 3);
    FloatImage gv(gpu.width, gpu.height, 1), rv(ref.width, ref.height, 1);
    for (size_t i = 0; i < size_t(gpu.width) * gpu.height; ++i)
        gv.pixels[i] = gpu.pixels[i * 4 + 3], rv.pixels[i] = ref.pixels[i * 4 + 3];
    HUSH_REQUIRE_IMAGES_MATCH(gv, rv, 3e-5f * scale * scale, 1e-4f);
}

} // namespace

TEST_CASE("svgf variance matches the CPU reference on the temporal and the 7x7 bilateral branch", "[svgf-variance]") {
    test::ValidationScope scope;
    for (auto size : {rhi::Extent2D{19, 13}, rhi::Extent2D{1, 1}, rhi::Extent2D{3, 5}, rhi::Extent2D{8, 6}}) {
        INFO(size.width << "x" << size.height);
        auto surface = testSurface(size.width, size.height);
        auto temporal = testTemporal(size.width, size.height, 3.0f, 51);
        for (const passes::SvgfVarianceSettings& s :
             {passes::SvgfVarianceSettings{}, passes::SvgfVarianceSettings{.shortHistoryBoost = false},
              passes::SvgfVarianceSettings{.minHistoryLength = 10.0f, .radius = 1},
              // a fractional normal exponent (pow()) and a whole one (repeated squaring)
              passes::SvgfVarianceSettings{.sigmaN = 60.5f}, passes::SvgfVarianceSettings{.sigmaN = 7.0f}}) {
            INFO("minHistory " << s.minHistoryLength << " radius " << s.radius << " boost " << s.shortHistoryBoost);
            auto gpu = runVariance(temporal, surface, s);
            requireVarianceMatch(gpu, reference::svgfVariance(temporal, surface, s), 3.0f);
        }
    }
    // Spot checks of the rule itself on the 19x13 image: history 9 is the temporal
    // variance as it is; a clamped mu2 < mu1^2 gives 0.
    auto surface = testSurface(19, 13);
    auto temporal = testTemporal(19, 13, 3.0f, 51);
    auto gpu = runVariance(temporal, surface);
    for (uint32_t y = 0; y < 13; ++y)
        for (uint32_t x = 0; x < 19; ++x) {
            if (temporal.moments.at(x, y, 2) != 9.0f) continue;
            const float m1 = temporal.moments.at(x, y, 0), m2 = temporal.moments.at(x, y, 1);
            REQUIRE(gpu.at(x, y, 3) == Approx(std::max(0.0f, m2 - m1 * m1)).margin(1e-5));
            REQUIRE(gpu.at(x, y, 0) == temporal.color.at(x, y, 0));
            if ((x + y) % 7 == 0) REQUIRE(gpu.at(x, y, 3) == 0.0f);
        }
    // Background (no normal) on the short branch keeps its own value: no neighbour weighs.
    REQUIRE(temporal.moments.at(0, 0, 2) == 1.0f);
    REQUIRE(gpu.at(0, 0, 1) == temporal.color.at(0, 0, 1));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

namespace {
// Temporal + variance on a static, flat surface, fed grey sample frames.
struct SequenceRig {
    NodeHarness t;
    passes::SvgfTemporal temporal;
    graph::TextureHandle variance;
    SequenceRig(uint32_t w, uint32_t h) : t({w, h}) {
        reference::SurfaceImages flat{FloatImage(w, h, 4), FloatImage(w, h, 4)};
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) flat.normalDepth.at(x, y, 2) = 1.0f, flat.normalDepth.at(x, y, 3) = 2.0f;
        auto illumination = t.input("illumination", FloatImage(w, h, 4));
        auto decision = t.input("decision", reference::identityDecision(w, h));
        temporal = passes::addSvgfTemporalPass(t.ctx, "temporal", illumination, decision);
        const passes::Surface surface{t.input("nd", flat.normalDepth), t.input("gm", flat.gradientMesh)};
        variance = passes::addSvgfVariancePass(t.ctx, "variance", temporal, surface);
        t.graph.markOutput(temporal.color);
        t.graph.markOutput(temporal.moments);
        t.graph.markOutput(variance);
    }
    FloatImage frame(const FloatImage& grey) {
        FloatImage rgb(grey.width, grey.height, 4, 1.0f);
        for (size_t i = 0; i < grey.pixels.size(); ++i)
            for (uint32_t c = 0; c < 3; ++c) rgb.pixels[i * 4 + c] = grey.pixels[i];
        t.update("illumination", rgb);
        t.graph.execute();
        t.graph.waitIdle();
        return readOutput(t.graph, variance);
    }
};
} // namespace

TEST_CASE("svgf variance of a known sample sequence: the population variance once the history holds 4 frames",
          "[svgf-variance]") {
    test::ValidationScope scope;
    const uint32_t w = 9, h = 7;
    SequenceRig rig(w, h);
    std::vector<FloatImage> samples;
    for (uint32_t f = 0; f < 5; ++f) {
        samples.push_back(randomImage(w, h, 1, 0.0f, 2.0f, 600 + f));
        auto gpu = rig.frame(samples.back());
        INFO("frame " << f);
        if (f + 1 < 4) {
            // Short history: the spatial estimate, checked against the reference on the
            // GPU's own integrated moments.
            reference::SvgfTemporalImages t{readOutput(rig.t.graph, rig.temporal.color),
                                            readOutput(rig.t.graph, rig.temporal.moments)};
            reference::SurfaceImages flat{FloatImage(w, h, 4), FloatImage(w, h, 4)};
            for (uint32_t y = 0; y < h; ++y)
                for (uint32_t x = 0; x < w; ++x)
                    flat.normalDepth.at(x, y, 2) = 1.0f, flat.normalDepth.at(x, y, 3) = 2.0f;
            requireVarianceMatch(gpu, reference::svgfVariance(t, flat, {}), 2.0f);
            continue;
        }
        // alpha = max(0.2, 1/n) = 1/n for n <= 5: moments are plain means of the samples.
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                double mean = 0, meanSq = 0;
                for (const auto& s : samples) mean += s.at(x, y), meanSq += double(s.at(x, y)) * s.at(x, y);
                mean /= double(samples.size()), meanSq /= double(samples.size());
                double population = 0;
                for (const auto& s : samples) population += (s.at(x, y) - mean) * (s.at(x, y) - mean);
                population /= double(samples.size());
                INFO(x << ", " << y);
                REQUIRE(gpu.at(x, y, 0) == Approx(mean).epsilon(1e-5));
                REQUIRE(gpu.at(x, y, 3) == Approx(population).margin(2e-5));
            }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("svgf variance converges to the exponential average's expected variance of uniform noise",
          "[svgf-variance]") {
    test::ValidationScope scope;
    const uint32_t w = 32, h = 32, frames = 40;
    SequenceRig rig(w, h);
    FloatImage gpu;
    for (uint32_t f = 0; f < frames; ++f) gpu = rig.frame(randomImage(w, h, 1, 0.0f, 1.0f, 700 + f));
    // Sample k's weight in the final average is a_k * prod_{j > k} (1 - a_j) with
    // a_n = max(0.2, 1 / n); for independent samples E[mu2 - mu1^2] = sigma^2 (1 - sum w^2).
    std::vector<double> weights(frames);
    for (uint32_t k = 1; k <= frames; ++k) {
        double wk = std::max(0.2, 1.0 / k);
        for (uint32_t j = k + 1; j <= frames; ++j) wk *= 1.0 - std::max(0.2, 1.0 / j);
        weights[k - 1] = wk;
    }
    double sumSq = 0;
    for (double wk : weights) sumSq += wk * wk;
    const double expected = (1.0 / 12.0) * (1.0 - sumSq);   // uniform [0, 1): sigma^2 = 1/12
    double mean = 0;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) mean += gpu.at(x, y, 3);
    mean /= double(w * h);
    // 1024 pixels of an estimate with about 9 effective samples: about 1.5 % standard error.
    INFO("mean variance " << mean << ", expected " << expected);
    REQUIRE(std::fabs(mean - expected) < 0.06 * expected);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("svgf variance: zero, 1e-30, 65504, 1e6 fireflies and extreme depths stay finite", "[svgf-variance]") {
    test::ValidationScope scope;
    for (auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{3, 5}, rhi::Extent2D{12, 9}}) {
        for (float v : {0.0f, 1e-30f, 65504.0f, 1e6f, 1e18f}) {
            INFO(size.width << "x" << size.height << " value " << v);
            const uint32_t w = size.width, h = size.height;
            // Fireflies of v in a dim image; moments as the temporal pass would hold them.
            reference::SvgfTemporalImages t{FloatImage(w, h, 4, 1.0f), FloatImage(w, h, 4)};
            for (uint32_t y = 0; y < h; ++y)
                for (uint32_t x = 0; x < w; ++x) {
                    const float c = (x + 2 * y) % 3 == 0 ? v : 0.01f;
                    for (uint32_t k = 0; k < 3; ++k) t.color.at(x, y, k) = c;
                    t.moments.at(x, y, 0) = 0.5f * c;
                    t.moments.at(x, y, 1) = 0.5f * c * c;
                    t.moments.at(x, y, 2) = float(1 + (x + y) % 5);
                }
            // Depth and slope at the value too (0: fronto-parallel at the camera).
            auto surface = testSurface(w, h);
            for (uint32_t y = 0; y < h; ++y)
                for (uint32_t x = 0; x < w; ++x) {
                    surface.normalDepth.at(x, y, 3) = v * float(1 + x % 2);
                    surface.gradientMesh.at(x, y, 0) = v;
                    surface.gradientMesh.at(x, y, 1) = -v;
                }
            auto gpu = runVariance(t, surface);
            REQUIRE(nonFiniteCount(gpu) == 0);
            requireVarianceMatch(gpu, reference::svgfVariance(t, surface, {}), std::max(v, 1.0f));
        }
    }
    // 1e6 fireflies through the temporal pass for a few frames: moments of 1e12 stay finite.
    SequenceRig rig(5, 4);
    for (uint32_t f = 0; f < 6; ++f) {
        auto grey = makeImage(5, 4, 1, [&](uint32_t x, uint32_t y, uint32_t) {
            return (x + y + f) % 4 == 0 ? 1e6f : 0.0f;
        });
        auto out = rig.frame(grey);
        REQUIRE(nonFiniteCount(out) == 0);
        REQUIRE(nonFiniteCount(readOutput(rig.t.graph, rig.temporal.moments)) == 0);
        for (float value : out.pixels) REQUIRE(value >= 0.0f);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
