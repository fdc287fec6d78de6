// MaraChain on tracer sequences (96x96, 16 frames): quality against the noisy input
// and EAW on every built-in scene, the glossy branch culled by the graph, a camera cut
// filled within two frames, a firefly that never shows, and what a frame without
// Mara's layers gets told.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>

#include <hush/passes/eaw/chain.hpp>
#include <hush/passes/mara/chain.hpp>
#include <hush/passes/metrics/metrics_evaluator.hpp>

#include "chain_test_util.hpp"
#include "pass_test_util.hpp"
#include "support/gpu_context.hpp"

using namespace hush;
using namespace hush::passes_test;

TEST_CASE("mara beats the noisy input on every built-in scene, and eaw on glossy and room", "[mara][mara-chain]") {
    test::ValidationScope scope;
    for (const std::string scene : {"cornell", "room", "glossy", "moving-light", "thin"}) {
        const auto& frames = sceneSequence(scene, 96);
        passes::MetricsEvaluator metrics(test::gpu().device, {96, 96});
        const Score noisy = noisyScore(frames, metrics);
        const Score mara = score(runSequence(std::make_unique<passes::MaraChain>(), frames), frames, metrics);
        const Score eaw = score(runSequence(std::make_unique<passes::EawChain>(), frames), frames, metrics);
        std::printf("mara quality 96x96 %s: RMSE noisy %.4f eaw %.4f mara %.4f | SSIM noisy %.4f eaw %.4f mara %.4f\n",
                    scene.c_str(), noisy.rmse, eaw.rmse, mara.rmse, noisy.ssim, eaw.ssim, mara.ssim);
        INFO(scene);
        CHECK(mara.rmse < noisy.rmse);
        CHECK(mara.ssim > noisy.ssim);
        if (scene == "glossy" || scene == "room") {
            CHECK(mara.rmse < eaw.rmse);
            CHECK(mara.ssim > eaw.ssim);
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("mara with glossy off: the graph culls every glossy pass and the matte result is unchanged",
          "[mara][mara-chain]") {
    test::ValidationScope scope;
    const auto& all = sceneSequence("glossy", 96);
    const std::vector<tracer::Frame> frames(all.begin(), all.begin() + 3);
    auto run = [&](passes::MaraGlossy mode, std::vector<std::string>& culled) {
        passes::MaraSettings s;
        s.glossy = mode;
        passes::ChainRunner runner(test::gpu().device, std::make_unique<passes::MaraChain>(s), {96, 96});
        const auto matte = runner.graph().findTexture("mara.matte.bilateral");
        REQUIRE(matte.valid());
        runner.graph().markOutput(matte);
        std::vector<FloatImage> out;
        for (const auto& f : frames) {
            uploadFrame(runner, f);
            runner.run();
            out.push_back(readOutput(runner.graph(), matte));
        }
        culled = runner.graph().culledPasses();
        return out;
    };
    std::vector<std::string> culledOn, culledOff;
    const auto on = run(passes::MaraGlossy::Auto, culledOn);
    const auto off = run(passes::MaraGlossy::Off, culledOff);
    for (const char* pass : {"mara.glossy.temporal", "mara.glossy.bilateral.horizontal", "mara.glossy.bilateral.vertical"}) {
        CHECK(std::count(culledOff.begin(), culledOff.end(), pass) == 1);
        CHECK(std::count(culledOn.begin(), culledOn.end(), pass) == 0);
    }
    for (size_t f = 0; f < frames.size(); ++f) HUSH_REQUIRE_IMAGES_MATCH(off[f], on[f], 0.0f, 0.0f);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("mara fills a camera cut within two frames: the radius grows where confidence drops", "[mara][mara-chain]") {
    test::ValidationScope scope;
    const auto& before = sceneSequence("cornell", 96);
    const auto& after = sceneSequence("room", 96);
    passes::MetricsEvaluator metrics(test::gpu().device, {96, 96});
    const auto reference = tonemappedRgba(after[15].get(tracer::Channel::Reference));
    // A cut nobody announces (no resetHistory): cornell's frames 0..7, then the room's
    // 14 and 15. The chain must find out from the positions alone.
    const auto steady = runSequence(std::make_unique<passes::MaraChain>(), after);
    passes::ChainRunner cut(test::gpu().device, std::make_unique<passes::MaraChain>(), {96, 96});
    const auto radius = cut.graph().findTexture("mara.matte.disocclusion");
    REQUIRE(radius.valid());
    cut.graph().markOutput(radius);
    auto meanRadius = [&] {
        const auto r = readOutput(cut.graph(), radius);
        double mean = 0.0;
        for (float v : r.pixels) mean += v / double(r.pixels.size());
        return mean;
    };
    for (size_t f = 0; f < 8; ++f) {
        uploadFrame(cut, before[f]);
        cut.run();
    }
    const double steadyRadius = meanRadius();
    uploadFrame(cut, after[14]);
    cut.run();
    const double cutRadius = meanRadius();
    uploadFrame(cut, after[15]);
    cut.run();
    const double afterCut = metrics.compare(cut.readDisplay(), reference).rmse;
    const double steadyRmse = metrics.compare(steady[15], reference).rmse;
    const double noisy = metrics.compare(tonemappedRgba(after[15].get(tracer::Channel::Color)), reference).rmse;
    std::printf("mara cut: mean disocclusion radius %.2f px before, %.2f px at the cut; RMSE two frames after "
                "%.4f, steady %.4f, noisy %.4f\n",
                steadyRadius, cutRadius, afterCut, steadyRmse, noisy);
    CHECK(cutRadius > 5.0 * steadyRadius);
    CHECK(afterCut < 0.75 * noisy);
    CHECK(afterCut < 1.5 * steadyRmse);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("mara: a 1e6 firefly in the matte term never shows and does not spread", "[mara][mara-chain]") {
    test::ValidationScope scope;
    const auto& all = sceneSequence("cornell", 96);
    const std::vector<tracer::Frame> frames(all.begin(), all.begin() + 8);
    constexpr size_t kFrame = 4;
    constexpr uint32_t kX = 48, kY = 60;   // on the floor
    const auto clean = runSequence(std::make_unique<passes::MaraChain>(), frames);
    const auto fired = runSequence(std::make_unique<passes::MaraChain>(), frames, [&](size_t f) -> ChannelEdit {
        if (f != kFrame) return {};
        return [](passes::InputChannel c, std::vector<float>& pixels, uint32_t components) {
            if (c != passes::InputChannel::Matte) return;
            for (uint32_t k = 0; k < components; ++k) pixels[(size_t(kY) * 96 + kX) * components + k] = 1e6f;
        };
    });
    for (size_t f = kFrame; f < frames.size(); ++f) {
        double worst = 0.0;
        for (size_t i = 0; i < clean[f].size(); ++i) worst = std::max(worst, double(std::fabs(fired[f][i] - clean[f][i])));
        INFO("frame " << f << ": largest display difference " << worst);
        CHECK(worst < 0.05);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("mara: a frame without Mara's layers is an error naming the layer and how to render it",
          "[mara][mara-chain]") {
    tracer::Frame frame = cornellSequence().front();   // no matte, glossy, virtualpos, roughness
    frame.add(tracer::Channel::Specular);              // (zero) so that matte is the first layer missing
    passes::ChainRunner runner(test::gpu().device, std::make_unique<passes::MaraChain>(), {96, 96},
                               {}, frames::channelsOf(frame));
    const auto error = test::errorFrom([&] { uploadFrame(runner, frame); });
    REQUIRE(error);
    CHECK(error->kind() == ErrorKind::NotFound);
    CHECK_THAT(error->what(), Catch::Contains("has no 'matte' layer, which chain 'mara' reads") &&
                                  Catch::Contains("hush render --channels all"));
    // The glossy layers are optional: none of them were asked for.
    const auto channels = runner.inputs().channels();
    CHECK(std::find(channels.begin(), channels.end(), passes::InputChannel::Glossy) == channels.end());
}
