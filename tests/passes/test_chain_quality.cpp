// The chains on a tracer sequence (the cornell box's camera path, 96x96, 16 frames):
// SVGF must beat the noisy input and the EAW baseline on SSIM against the reference,
// and its temporal error must be below EAW's and at least 5x below the input's
// (SVGF Sec. 5: about 10x lower temporal error than prior interactive filters).
// BMFR must beat the noisy input, and EAW once its block size suits the resolution
// (see the BMFR case; Koskela et al. 2019 Sec. 7.1).
#include <catch2/catch.hpp>

#include <cstdio>

#include <hush/passes/bmfr/chain.hpp>
#include <hush/passes/chain_file.hpp>
#include <hush/tracer/builtin_scenes.hpp>
#include <hush/passes/eaw/chain.hpp>
#include <hush/passes/metrics/metrics_evaluator.hpp>
#include <hush/passes/svgf/chain.hpp>

#include "chain_test_util.hpp"
#include "support/gpu_context.hpp"

using namespace hush;
using namespace hush::passes_test;

TEST_CASE("svgf beats the noisy input and eaw on ssim and temporal error", "[chain][quality]") {
    test::ValidationScope scope;
    const auto& frames = cornellSequence();
    passes::MetricsEvaluator metrics(test::gpu().device, {frames[0].width, frames[0].height});

    const Score input = noisyScore(frames, metrics);
    const Score eaw = score(runSequence(std::make_unique<passes::EawChain>(), frames), frames, metrics);
    const Score svgf = score(runSequence(std::make_unique<passes::SvgfChain>(), frames), frames, metrics);
    std::printf("quality 96x96 cornell, 16 frames: SSIM noisy %.4f eaw %.4f svgf %.4f | RMSE noisy %.4f eaw %.4f "
                "svgf %.4f | temporal noisy %.5f eaw %.5f svgf %.5f\n",
                input.ssim, eaw.ssim, svgf.ssim, input.rmse, eaw.rmse, svgf.rmse, input.temporal, eaw.temporal,
                svgf.temporal);
    CHECK(svgf.ssim > input.ssim);
    CHECK(svgf.ssim > eaw.ssim);
    CHECK(svgf.rmse < eaw.rmse);
    CHECK(eaw.ssim > input.ssim);
    CHECK(svgf.temporal < eaw.temporal);
    CHECK(svgf.temporal * 5.0 < input.temporal);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

// BMFR at 96x96. With the paper's constants (32 x 32 blocks, TAA on) it beats the
// noisy input but not EAW at this size (measured: SSIM 0.9485 vs 0.9529, RMSE 0.0166
// vs 0.0166): a 32-pixel block is sized for 1280x720 (Sec. 6.1); at 96x96 one block
// covers 1/9 of the image (at 720p 1/900), too large for the features to represent
// the lighting in it (Sec. 8 (1)), and "TAA decreases the quality measured by the
// objective quality metrics" (Sec. 7.1). So at 96x96 the comparison with EAW uses
// blocks scaled to the resolution (16 px) without TAA; the next test checks the
// paper's defaults against EAW at 128x128. docs/passes/bmfr-chain.md quotes both.
TEST_CASE("bmfr beats the noisy input, and with blocks scaled to 96x96 and no TAA also eaw, on rmse and ssim",
          "[chain][quality][bmfr]") {
    test::ValidationScope scope;
    const auto& frames = cornellSequence();
    passes::MetricsEvaluator metrics(test::gpu().device, {frames[0].width, frames[0].height});

    const Score input = noisyScore(frames, metrics);
    const Score eaw = score(runSequence(std::make_unique<passes::EawChain>(), frames), frames, metrics);
    passes::BmfrSettings paperSettings;
    paperSettings.fit.blockSize = 32;   // the paper's constant (the default follows the frame: 16 here)
    const Score paper = score(runSequence(std::make_unique<passes::BmfrChain>(paperSettings), frames), frames, metrics);
    passes::BmfrSettings scaled;
    scaled.fit.blockSize = 16;
    scaled.back.useTaa = false;
    const Score small = score(runSequence(std::make_unique<passes::BmfrChain>(scaled), frames), frames, metrics);
    std::printf("quality 96x96 cornell, 16 frames: SSIM noisy %.4f eaw %.4f bmfr %.4f (16-px blocks, no TAA %.4f) | "
                "RMSE noisy %.4f eaw %.4f bmfr %.4f (%.4f) | temporal noisy %.5f eaw %.5f bmfr %.5f (%.5f)\n",
                input.ssim, eaw.ssim, paper.ssim, small.ssim, input.rmse, eaw.rmse, paper.rmse, small.rmse,
                input.temporal, eaw.temporal, paper.temporal, small.temporal);
    CHECK(paper.ssim > input.ssim);
    CHECK(paper.rmse < input.rmse);
    // Two temporal accumulations and TAA: far steadier than the input.
    CHECK(paper.temporal * 5.0 < input.temporal);
    CHECK(small.ssim > eaw.ssim);
    CHECK(small.rmse < eaw.rmse);
    CHECK(small.temporal < eaw.temporal);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

// At 128x128 the paper's own configuration (32-pixel blocks, TAA) beats EAW on both.
TEST_CASE("bmfr with the paper's constants beats the noisy input and eaw on rmse and ssim at 128x128",
          "[chain][quality][bmfr]") {
    test::ValidationScope scope;
    const auto& frames = cornellSequence128();
    passes::MetricsEvaluator metrics(test::gpu().device, {frames[0].width, frames[0].height});
    const Score input = noisyScore(frames, metrics);
    const Score eaw = score(runSequence(std::make_unique<passes::EawChain>(), frames), frames, metrics);
    passes::BmfrSettings paper;
    paper.fit.blockSize = 32;
    const Score bmfr = score(runSequence(std::make_unique<passes::BmfrChain>(paper), frames), frames, metrics);
    std::printf("quality 128x128 cornell, 16 frames: SSIM noisy %.4f eaw %.4f bmfr %.4f | RMSE noisy %.4f eaw %.4f "
                "bmfr %.4f | temporal noisy %.5f eaw %.5f bmfr %.5f\n",
                input.ssim, eaw.ssim, bmfr.ssim, input.rmse, eaw.rmse, bmfr.rmse, input.temporal, eaw.temporal,
                bmfr.temporal);
    CHECK(bmfr.ssim > input.ssim);
    CHECK(bmfr.rmse < input.rmse);
    CHECK(bmfr.ssim > eaw.ssim);
    CHECK(bmfr.rmse < eaw.rmse);
    CHECK(bmfr.temporal < eaw.temporal);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

// Issue 15's bar: every shipped chain at its defaults beats the noisy input on RMSE and
// SSIM on every built-in scene, scored as hush-bench-chains, hush sweep and hush demo
// score (tonemapped, against the anti-aliased reference). BMFR on `glossy` at 128x128
// lost to the input with 16-pixel blocks (RMSE 0.121 vs 0.114); its default of 8-pixel
// blocks below 255 lines beats it (docs/sweep.md).
void requireEveryChainBeatsTheInput(const std::string& scene, uint32_t size) {
    test::ValidationScope scope;
    passes::MetricsEvaluator metrics(test::gpu().device, {size, size});
    const auto& frames = benchSequence(scene, size);
    const Score input = noisyScore(frames, metrics);
    for (const auto& chain : passes::builtinChainNames()) {
        const Score s = score(runSequence(passes::makeBuiltinChain(chain), frames), frames, metrics);
        std::printf("quality %ux%u %s %s: RMSE %.4f (noisy %.4f), SSIM %.4f (noisy %.4f)\n", size, size,
                    scene.c_str(), chain.c_str(), s.rmse, input.rmse, s.ssim, input.ssim);
        INFO(chain << " on " << scene << " at " << size);
        CHECK(s.rmse < input.rmse);
        CHECK(s.ssim > input.ssim);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

// One test case per scene and size, so that CTest runs them in parallel and each
// renders one scene (the 256x256 set took 876 s as one test beside the suite).
#define HUSH_ALL_SCENES_CASE(scene, size)                                                                        \
    TEST_CASE("every shipped chain beats the noisy input on rmse and ssim at " #size "x" #size ": " scene,         \
              "[chain][quality][all-scenes]") {                                                                  \
        requireEveryChainBeatsTheInput(scene, size);                                                             \
    }
HUSH_ALL_SCENES_CASE("cornell", 128)
HUSH_ALL_SCENES_CASE("room", 128)
HUSH_ALL_SCENES_CASE("glossy", 128)
HUSH_ALL_SCENES_CASE("moving-light", 128)
HUSH_ALL_SCENES_CASE("thin", 128)
HUSH_ALL_SCENES_CASE("cornell", 256)
HUSH_ALL_SCENES_CASE("room", 256)
HUSH_ALL_SCENES_CASE("glossy", 256)
HUSH_ALL_SCENES_CASE("moving-light", 256)
HUSH_ALL_SCENES_CASE("thin", 256)

TEST_CASE("the all-scenes quality cases cover every built-in scene", "[chain][quality]") {
    const std::vector<std::string> covered{"cornell", "room", "glossy", "moving-light", "thin"};
    CHECK(tracer::builtinSceneNames() == covered);
}
