// RdaeChain on tracer sequences: the shipped default weights against the noisy input,
// EAW and their recorded quality on every built-in scene (cornell was held out of
// training), and, with a small random network (tests/passes/data), the chain's
// plumbing: the recurrence carries state through the chain and a reset clears it,
// NaN/Inf never reach an output or a hidden state, odd sizes, and the errors for
// weights that do not fit.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include <hush/passes/eaw/chain.hpp>
#include <hush/passes/metrics/metrics_evaluator.hpp>
#include <hush/passes/rdae/chain.hpp>

#include "chain_test_util.hpp"
#include "pass_test_util.hpp"
#include "support/gpu_context.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

// A random width-4, 2-level network: the chain's plumbing, whatever the training did.
passes::RdaeSettings smallNetwork() {
    passes::RdaeSettings s;
    s.width = 4;
    s.levels = 2;
    s.weights = std::string(HUSH_PASSES_TEST_DATA_DIR) + "/rdae_random_w4_l2.safetensors";
    return s;
}

} // namespace

// The shipped default weights were trained far less than the paper's (docs/rdae-training.md):
// they beat EAW where 1-spp noise dominates, not everywhere. What the test holds them to:
// less flicker than the input on every scene; better RMSE, SSIM and flicker than the
// input and EAW on the noise-dominated scenes (room, moving-light); and on every scene
// no worse than the figures recorded when the weights shipped (docs/passes/rdae.md,
// "Quality of the shipped weights"), 3 % slack, so that a change to inference or to the
// weights that costs quality fails.
struct RecordedQuality {
    const char* scene;
    double rmse, ssim, temporal;
};
constexpr RecordedQuality kShipped[] = {
    {"cornell", 0.0297, 0.8797, 0.00181},
    {"room", 0.0879, 0.7633, 0.00785},
    {"glossy", 0.0962, 0.7628, 0.02241},
    {"moving-light", 0.0966, 0.6678, 0.00728},
    {"thin", 0.1534, 0.6501, 0.06440},
};

TEST_CASE("rdae (shipped weights): less flicker than the input everywhere, beats eaw where noise dominates, "
          "and holds its recorded quality",
          "[rdae][rdae-chain]") {
    test::ValidationScope scope;
    for (const RecordedQuality& recorded : kShipped) {
        const std::string scene = recorded.scene;
        const auto& frames = sceneSequence(scene, 96);
        passes::MetricsEvaluator metrics(test::gpu().device, {96, 96});
        const Score noisy = noisyScore(frames, metrics);
        const Score rdae = score(runSequence(std::make_unique<passes::RdaeChain>(), frames), frames, metrics);
        // The baseline as published (Dammertz et al.'s absolute colour sigma): hush's
        // default EAW, scale-free since issue 17, beats these weights on moving-light.
        passes::EawChainSettings published;
        published.atrous.sigmaRtRelative = 0.0f;
        const Score eaw = score(runSequence(std::make_unique<passes::EawChain>(published), frames), frames, metrics);
        std::printf("rdae quality 96x96 %s%s: RMSE noisy %.4f eaw(absolute) %.4f rdae %.4f | SSIM noisy %.4f eaw %.4f rdae "
                    "%.4f | temporal noisy %.5f eaw %.5f rdae %.5f\n",
                    scene.c_str(), scene == "cornell" ? " (held out)" : "", noisy.rmse, eaw.rmse, rdae.rmse,
                    noisy.ssim, eaw.ssim, rdae.ssim, noisy.temporal, eaw.temporal, rdae.temporal);
        INFO(scene);
        CHECK(rdae.temporal < noisy.temporal);
        if (scene == "room" || scene == "moving-light") {
            CHECK(rdae.rmse < noisy.rmse);
            CHECK(rdae.ssim > noisy.ssim);
            CHECK(rdae.rmse < eaw.rmse);
            CHECK(rdae.ssim > eaw.ssim);
            CHECK(rdae.temporal < eaw.temporal);
        }
        CHECK(rdae.rmse <= recorded.rmse * 1.03);
        CHECK(rdae.ssim >= recorded.ssim * 0.97);
        CHECK(rdae.temporal <= recorded.temporal * 1.03);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("rdae chain: the hidden state changes the next frame, and a reset clears it", "[rdae][rdae-chain]") {
    test::ValidationScope scope;
    const auto& frames = sceneSequence("cornell", 96);
    auto settings = smallNetwork();
    settings.back.useTaa = false;   // the network's own state only
    passes::ChainRunner a(test::gpu().device, std::make_unique<passes::RdaeChain>(settings), {96, 96});
    passes::ChainRunner b(test::gpu().device, std::make_unique<passes::RdaeChain>(settings), {96, 96});
    for (size_t f = 0; f < 3; ++f) {
        uploadFrame(a, frames[f]);
        a.run();
    }
    uploadFrame(b, frames[2]);
    b.run();                                   // frame 2 as a first frame
    const auto withHistory = a.readRadiance(), fresh = b.readRadiance();
    CHECK(relativeL1(withHistory, fresh) > 1e-3);
    a.resetHistory();
    uploadFrame(a, frames[2]);
    a.run();
    CHECK(relativeL1(a.readRadiance(), fresh) == 0.0);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("rdae chain: NaN and Inf in every input never reach an output or a hidden state", "[rdae][rdae-chain]") {
    test::ValidationScope scope;
    const auto& frames = sceneSequence("glossy", 96);
    passes::ChainRunner runner(test::gpu().device, std::make_unique<passes::RdaeChain>(smallNetwork()), {96, 96});
    const auto hidden = markHistorySources(runner.graph());
    REQUIRE(hidden.size() >= 2);   // the two RCNN blocks (and TAA's history)
    for (size_t f = 0; f < 4; ++f) {
        uploadFrame(runner, frames[f], [&](passes::InputChannel, std::vector<float>& pixels, uint32_t components) {
            for (size_t i = 0; i < pixels.size(); i += 7 * components + 1)
                pixels[i] = (i / 7) % 2 ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
        });
        runner.run();
        CHECK(nonFinite(runner.readDisplay()) == 0);
        CHECK(nonFinite(runner.readRadiance()) == 0);
        for (const auto h : hidden) CHECK(nonFinite(runner.readTexture(h)) == 0);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("rdae chain: 1x1, 37x53 and other sizes off the pooling multiple", "[rdae][rdae-chain]") {
    test::ValidationScope scope;
    const auto& source = sceneSequence("cornell", 96);
    for (const auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{37, 53}, rhi::Extent2D{65, 3}}) {
        INFO(size.width << "x" << size.height);
        passes::ChainRunner runner(test::gpu().device, std::make_unique<passes::RdaeChain>(smallNetwork()), size);
        for (size_t f = 0; f < 2; ++f) {
            tracer::Frame frame = source[f];
            frame.width = size.width;
            frame.height = size.height;
            for (auto& [channel, image] : frame.channels) {   // the top-left corner of the 96x96 frame
                tracer::Image crop(size.width, size.height, image.channels);
                for (uint32_t y = 0; y < size.height; ++y)
                    for (uint32_t x = 0; x < size.width; ++x)
                        std::copy_n(image.at(x, y), image.channels, crop.at(x, y));
                image = crop;
            }
            uploadFrame(runner, frame);
            runner.run();
            const auto display = runner.readDisplay();
            CHECK(display.size() == size_t(size.width) * size.height * 4);
            CHECK(nonFinite(display) == 0);
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("rdae chain: weights that do not fit name the file and what is wrong", "[rdae][rdae-chain]") {
    auto wrongWidth = smallNetwork();
    wrongWidth.width = 8;   // the file holds a width-4 network
    CHECK_THROWS_WITH(passes::ChainRunner(test::gpu().device, std::make_unique<passes::RdaeChain>(wrongWidth), {8, 8}),
                      Catch::Contains("rdae_random_w4_l2.safetensors") && Catch::Contains("'width' is 4"));
    passes::RdaeSettings unknown;
    unknown.width = 24;
    CHECK_THROWS_WITH(passes::ChainRunner(test::gpu().device, std::make_unique<passes::RdaeChain>(unknown), {8, 8}),
                      Catch::Contains("no built-in weights for width 24"));
    auto missing = smallNetwork();
    missing.weights = "/nonexistent/rdae.safetensors";
    CHECK_THROWS_WITH(passes::ChainRunner(test::gpu().device, std::make_unique<passes::RdaeChain>(missing), {8, 8}),
                      Catch::Contains("/nonexistent/rdae.safetensors") && Catch::Contains("no such file"));
}
