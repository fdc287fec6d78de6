// passes/bmfr/fit: the block grid, and the GPU fit against the double-precision CPU
// reference with the same features, noise and guards.
//
// Tolerance (GPU fp32 vs CPU double, same noise): max |diff| <= 2e-3 x the RMS of the
// reference output; measured 1e-6 .. 5e-5 of it (docs/passes/bmfr.md). The fp32 QR
// loses about cond([T + N]) x 6e-8 in relative accuracy; with eps = 0.01 and the
// nearly collinear w and w^2 of a small block, cond reaches 1e3..1e4, so a few 1e-4
// of the colour scale is the expected fp32 error, far below the fit's own error.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

#include "test_bmfr_scenes.hpp"

using namespace hush;
using namespace hush::passes_test;
using namespace hush::passes_test::bmfr;

TEST_CASE("bmfr block grid covers every pixel once for every offset and block size", "[bmfr]") {
    for (uint32_t B : {16u, 32u, 64u}) {
        for (auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{70, 45}, rhi::Extent2D{128, 128}}) {
            std::set<std::pair<uint32_t, uint32_t>> offsets;
            for (uint64_t frame = 0; frame < 16; ++frame) {
                const auto g = passes::bmfrBlockGrid(size, B, true, frame);
                offsets.insert({g.offsetX, g.offsetY});
                REQUIRE(g.offsetX < B);
                REQUIRE(g.offsetY < B);
                // Every pixel in exactly one block (pixel + offset divided by B), and
                // every block holds at least one pixel.
                std::vector<uint32_t> perBlock(size_t(g.blocksX) * g.blocksY, 0);
                bool inGrid = true;
                for (uint32_t y = 0; y < size.height; ++y) {
                    for (uint32_t x = 0; x < size.width; ++x) {
                        const uint32_t bx = (x + g.offsetX) / B, by = (y + g.offsetY) / B;
                        inGrid = inGrid && bx < g.blocksX && by < g.blocksY;
                        if (bx < g.blocksX && by < g.blocksY) ++perBlock[size_t(by) * g.blocksX + bx];
                    }
                }
                REQUIRE(inGrid);
                REQUIRE(std::count(perBlock.begin(), perBlock.end(), 0u) == 0);
            }
            CHECK(offsets.size() == 16);   // 16 distinct displacements
            CHECK(passes::bmfrBlockGrid(size, B, false, 5).offsetX == 0);
        }
    }
}

TEST_CASE("bmfr noise is uniform in [-eps, eps] with zero mean", "[bmfr]") {
    double sum = 0.0, sum2 = 0.0, lo = 1.0, hi = -1.0;
    const int n = 64 * 64 * 10;
    for (int i = 0; i < n; ++i) {
        const double v = reference::bmfrNoise(uint32_t(i % 64), uint32_t(i / 64 % 64), 3, uint32_t(i / 4096), 0.01f);
        sum += v, sum2 += v * v, lo = std::min(lo, v), hi = std::max(hi, v);
    }
    CHECK(std::fabs(sum / n) < 2e-4);                        // 0 +- a few standard errors (0.0058 / 202)
    CHECK(sum2 / n == Approx(0.01 * 0.01 / 3).epsilon(0.03));   // variance eps^2 / 3 (Sec. 3.2)
    CHECK(lo >= -0.01);
    CHECK(hi < 0.01);
    CHECK(lo < -0.0099);
    CHECK(hi > 0.0099);
}

TEST_CASE("bmfr block size 0 keeps the paper's block count: 32 pixels at 720 lines, scaled and rounded", "[bmfr]") {
    using passes::bmfrBlockSizeFor;
    CHECK(bmfrBlockSizeFor({1280, 720}, 0) == 32);   // the paper's frame
    CHECK(bmfrBlockSizeFor({128, 128}, 0) == 8);
    CHECK(bmfrBlockSizeFor({16, 8}, 0) == 8);
    CHECK(bmfrBlockSizeFor({256, 254}, 0) == 8);     // the boundaries: geometric means of 8, 16, 32, 64
    CHECK(bmfrBlockSizeFor({256, 255}, 0) == 16);
    CHECK(bmfrBlockSizeFor({256, 256}, 0) == 16);
    CHECK(bmfrBlockSizeFor({640, 360}, 0) == 16);
    CHECK(bmfrBlockSizeFor({4096, 509}, 0) == 16);
    CHECK(bmfrBlockSizeFor({16, 510}, 0) == 32);
    CHECK(bmfrBlockSizeFor({16, 1018}, 0) == 32);
    CHECK(bmfrBlockSizeFor({16, 1019}, 0) == 64);
    CHECK(bmfrBlockSizeFor({3840, 2160}, 0) == 64);
    for (uint32_t B : {8u, 16u, 32u, 64u}) CHECK(bmfrBlockSizeFor({128, 128}, B) == B);   // given: kept
}

TEST_CASE("bmfr fit matches the CPU reference on random blocks", "[bmfr]") {
    test::ValidationScope scope;
    for (uint32_t B : {0u, 8u, 16u, 32u, 64u}) {   // 0: follows the frame (16 here)
        const Scene sc = randomScene(48, 40, 100 + B);
        passes::BmfrFitSettings s;
        s.blockSize = B;
        const auto gpu = runFit(sc, s);
        const auto ref = reference::bmfrFit(sc.images(), s, 0);
        const Diff d = diff(gpu, ref);
        INFO("B " << B << ": max |gpu - cpu| " << d.maxAbs << ", rms " << d.rms << ", output rms " << d.scale);
        CHECK(nonFiniteCount(gpu) == 0);
        REQUIRE(d.maxAbs <= 2e-3 * d.scale);
        // A fit on random features explains little: the output is near each block's
        // mean, not the input (sanity check that the test can fail).
        CHECK(diff(gpu, sc.illumination).rms > 0.1);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

// Block size 0 picks a shader per frame size: each pick runs with its own pipeline's
// push constants (a regression: 32- and 64-pixel frames once used the 16-pixel one's).
TEST_CASE("bmfr fit with block size 0 follows tall frames to 32- and 64-pixel blocks", "[bmfr]") {
    test::ValidationScope scope;
    for (uint32_t height : {520u, 1030u}) {   // bmfrBlockSizeFor: 32, then 64
        const Scene sc = randomScene(24, height, height);
        passes::BmfrFitSettings s;
        s.blockSize = 0;
        const auto gpu = runFit(sc, s);
        const auto ref = reference::bmfrFit(sc.images(), s, 0);
        const Diff d = diff(gpu, ref);
        INFO("height " << height << " (block " << passes::bmfrBlockSizeFor({24, height}, 0) << "): max |gpu - cpu| "
                       << d.maxAbs << ", output rms " << d.scale);
        CHECK(nonFiniteCount(gpu) == 0);
        REQUIRE(d.maxAbs <= 2e-3 * d.scale);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("bmfr fit matches the CPU reference on a plane and a sphere, over several frames", "[bmfr]") {
    test::ValidationScope scope;
    const Scene sc = realLookingScene(64, 64, 7);
    passes::BmfrFitSettings s;
    s.blockSize = 32;   // the paper's: 1024 rows per block (the figures below are for it)
    for (uint32_t frames : {1u, 2u, 5u}) {   // frames 0, 1, 4: three grid offsets, three noise draws
        const auto gpu = runFit(sc, s, frames);
        const auto ref = reference::bmfrFit(sc.images(), s, frames - 1);
        const Diff d = diff(gpu, ref);
        INFO("frame " << frames - 1 << ": max |gpu - cpu| " << d.maxAbs << ", output rms " << d.scale);
        CHECK(nonFiniteCount(gpu) == 0);
        REQUIRE(d.maxAbs <= 2e-3 * d.scale);
        // The fit denoises: its error against the noise-free lighting is the features'
        // bias (the clean lighting's own projection error) plus a small remainder of
        // the input noise (measured: 0.011 against the input's 0.066 rms).
        Scene cleanScene = sc;
        cleanScene.illumination = sc.clean;
        const double bias = diff(reference::bmfrProjection(cleanScene.images(), s, frames - 1), sc.clean).rms;
        const double fit = diff(gpu, sc.clean).rms, input = diff(sc.illumination, sc.clean).rms;
        INFO("rms vs clean: bias " << bias << ", fit " << fit << ", input " << input);
        CHECK(std::sqrt(std::max(0.0, fit * fit - bias * bias)) < 0.3 * input);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("bmfr fit with albedo, roughness, mesh id and in-block gradients matches the reference", "[bmfr]") {
    test::ValidationScope scope;
    const Scene sc = realLookingScene(40, 36, 21);
    using F = passes::BmfrFeature;
    passes::BmfrFitSettings s;
    s.blockSize = 16;
    s.features = {F::One, F::NormalX, F::NormalY, F::NormalZ, F::PositionX, F::PositionY, F::PositionZ,
                  F::AlbedoR, F::AlbedoG, F::AlbedoB, F::Roughness, F::MeshId, F::BlockU, F::BlockV,
                  F::PositionX2, F::PositionY2, F::PositionZ2};   // all 17
    const auto gpu = runFit(sc, s, 3);
    const auto ref = reference::bmfrFit(sc.images(), s, 2);
    const Diff d = diff(gpu, ref);
    INFO("max |gpu - cpu| " << d.maxAbs << ", output rms " << d.scale);
    CHECK(nonFiniteCount(gpu) == 0);
    REQUIRE(d.maxAbs <= 2e-3 * d.scale);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("bmfr fit rejects bad settings and missing guides", "[bmfr]") {
    NodeHarness t({8, 8});
    const auto img = randomImage(8, 8, 3, 0.0f, 1.0f, 1);
    auto illum = t.input("illumination", img);
    passes::BmfrGuide g{t.input("normal", img), t.input("position", img), {}, {}, {}};
    auto bad = [&](passes::BmfrFitSettings s, const passes::BmfrGuide& guide) {
        CHECK_THROWS_AS(passes::addBmfrFitPass(t.ctx, "bmfr.fit", illum, guide, s), Error);
    };
    passes::BmfrFitSettings s;
    s.blockSize = 24;
    bad(s, g);
    s = {};
    s.epsilon = -1.0f;
    bad(s, g);
    s = {};
    s.features.clear();
    bad(s, g);
    s = {};
    s.features.push_back(passes::BmfrFeature::AlbedoR);   // no albedo guide
    bad(s, g);
    s = {};
    s.features.assign(18, passes::BmfrFeature::One);
    bad(s, g);
    // Without position features the position guide may be absent.
    passes::BmfrGuide normalOnly{g.normal, {}, {}, {}, {}};
    s = {};
    s.features = {passes::BmfrFeature::One, passes::BmfrFeature::NormalX};
    CHECK_NOTHROW(passes::addBmfrFitPass(t.ctx, "bmfr.fit2", illum, normalOnly, s));
}

// fit.nonNegative (the default): beside fireflies a block's fit rings below 0; the
// node sets those values to 0 and scales the block's others to keep its sum.
TEST_CASE("bmfr fit beside fireflies is non-negative and keeps each block's sum, as the CPU reference", "[bmfr]") {
    test::ValidationScope scope;
    Scene sc = realLookingScene(32, 24, 11);
    for (uint32_t y = 0; y < sc.height(); ++y)
        for (uint32_t x = 0; x < sc.width(); ++x)
            if ((x * 7 + y * 13) % 29 == 0)
                for (uint32_t c = 0; c < 3; ++c) sc.illumination.at(x, y, c) = 1e4f;
    passes::BmfrFitSettings s;
    s.blockSize = 8;
    s.offsetBlocks = false;   // blocks at multiples of 8: the sums below are per block
    passes::BmfrFitSettings plain = s;
    plain.nonNegative = false;
    const auto gpu = runFit(sc, s), gpuPlain = runFit(sc, plain);
    const auto ref = reference::bmfrFit(sc.images(), s, 0);
    const Diff d = diff(gpu, ref);
    INFO("max |gpu - cpu| " << d.maxAbs << ", output rms " << d.scale);
    REQUIRE(d.maxAbs <= 2e-3 * d.scale);
    REQUIRE(diff(gpuPlain, reference::bmfrFit(sc.images(), plain, 0)).maxAbs <= 2e-3 * d.scale);
    float plainMin = 0.0f, lo = 0.0f;
    for (uint32_t by = 0; by < 3; ++by)
        for (uint32_t bx = 0; bx < 4; ++bx)
            for (uint32_t c = 0; c < 3; ++c) {
                double sum = 0.0, plainSum = 0.0;
                for (uint32_t y = by * 8; y < by * 8 + 8; ++y)
                    for (uint32_t x = bx * 8; x < bx * 8 + 8; ++x) {
                        sum += gpu.at(x, y, c);
                        plainSum += gpuPlain.at(x, y, c);
                        lo = std::min(lo, gpu.at(x, y, c));
                        plainMin = std::min(plainMin, gpuPlain.at(x, y, c));
                    }
                INFO("block " << bx << ", " << by << " channel " << c << ": sum " << sum << ", plain " << plainSum);
                CHECK(sum == Approx(plainSum).epsilon(1e-4));
            }
    CHECK(plainMin < -1.0f);   // the case exercises the ringing
    CHECK(lo == 0.0f);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
