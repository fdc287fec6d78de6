// The chains on a tracer sequence (the cornell box's camera path, 96x96, 16 frames):
// SVGF must beat the noisy input and the EAW baseline on SSIM against the reference,
// and its temporal error must be below EAW's and at least 5x below the input's
// (SVGF Sec. 5: about 10x lower temporal error than prior interactive filters).
#include <catch2/catch.hpp>

#include <cstdio>

#include <hush/passes/eaw/chain.hpp>
#include <hush/passes/metrics/metrics_evaluator.hpp>
#include <hush/passes/svgf/chain.hpp>

#include "chain_test_util.hpp"
#include "support/gpu_context.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

struct Score {
    double ssim = 0.0, rmse = 0.0, temporal = 0.0;
};

Score score(const std::vector<std::vector<float>>& displays, const std::vector<tracer::Frame>& frames,
            passes::MetricsEvaluator& metrics) {
    Score s;
    int scored = 0;
    for (size_t f = 0; f < frames.size(); ++f) {
        if (f > 0) s.temporal += metrics.temporalError(displays[f], displays[f - 1]) / double(frames.size() - 1);
        if (!frames[f].has(tracer::Channel::Reference)) continue;
        const auto reference = tonemappedRgba(frames[f].get(tracer::Channel::Reference));
        const auto m = metrics.compare(displays[f], reference);
        s.ssim += m.ssim;
        s.rmse += m.rmse;
        ++scored;
    }
    s.ssim /= scored;
    s.rmse /= scored;
    return s;
}

} // namespace

TEST_CASE("svgf beats the noisy input and eaw on ssim and temporal error", "[chain][quality]") {
    test::ValidationScope scope;
    const auto& frames = cornellSequence();
    passes::MetricsEvaluator metrics(test::gpu().device, {frames[0].width, frames[0].height});

    std::vector<std::vector<float>> noisy;
    for (const auto& f : frames) noisy.push_back(tonemappedRgba(f.get(tracer::Channel::Color)));
    const Score input = score(noisy, frames, metrics);
    const Score eaw = score(runSequence(std::make_unique<passes::EawChain>(), frames), frames, metrics);
    const Score svgf = score(runSequence(std::make_unique<passes::SvgfChain>(), frames), frames, metrics);
    std::printf("quality 96x96 cornell, 16 frames: SSIM noisy %.4f eaw %.4f svgf %.4f | RMSE noisy %.4f eaw %.4f "
                "svgf %.4f | temporal noisy %.5f eaw %.5f svgf %.5f\n",
                input.ssim, eaw.ssim, svgf.ssim, input.rmse, eaw.rmse, svgf.rmse, input.temporal, eaw.temporal,
                svgf.temporal);
    CHECK(svgf.ssim > input.ssim);
    CHECK(svgf.ssim > eaw.ssim);
    CHECK(eaw.ssim > input.ssim);
    CHECK(svgf.temporal < eaw.temporal);
    CHECK(svgf.temporal * 5.0 < input.temporal);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
