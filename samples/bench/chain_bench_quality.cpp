// hush-bench-chains, quality: every chain on a short sequence of every built-in
// tracer scene, scored as `hush denoise` scores it: the chains' display output and
// the noisy input and the reference tonemapped with the chains' default curve
// (passes::tonemap), RMSE / PSNR / SSIM against the reference on the frames that
// have one, temporal error between consecutive frames (metrics/*.hpp).
#include <algorithm>
#include <chrono>
#include <cstdio>

#include <hush/passes/chain_file.hpp>
#include <hush/passes/common/tonemap.hpp>
#include <hush/passes/metrics/metrics_evaluator.hpp>
#include <hush/core/error.hpp>
#include <hush/tracer/builtin_scenes.hpp>
#include <hush/tracer/renderer.hpp>

#include "chain_bench.hpp"
#include "frame_upload.hpp"

namespace hush::bench::chain_bench {
namespace {

using Clock = std::chrono::steady_clock;
using Image = std::vector<float>;   // RGBA, width * height * 4

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// A 3-component HDR tracer image as display values (RGBA, alpha 1) with the chains'
// default tonemap, as the CLI treats the noisy input and the reference.
Image tonemapped(const tracer::Image& hdr) {
    Image out(size_t(hdr.width) * hdr.height * 4, 1.0f);
    const passes::TonemapSettings settings;
    for (size_t i = 0; i < size_t(hdr.width) * hdr.height; ++i) {
        for (size_t c = 0; c < 3 && c < hdr.channels; ++c) out[i * 4 + c] = hdr.pixels[i * hdr.channels + c];
        passes::tonemap(settings, &out[i * 4]);
    }
    return out;
}

bool hasReference(const Options& options, uint32_t frame) {
    return std::find(options.referenceFrames.begin(), options.referenceFrames.end(), frame) !=
           options.referenceFrames.end();
}

std::vector<tracer::Frame> renderSequence(const std::string& scene, const Options& options) {
    const tracer::Renderer renderer(tracer::makeBuiltinScene(scene));
    tracer::RenderSettings settings;
    settings.width = options.qualitySize.width;
    settings.height = options.qualitySize.height;
    settings.referenceSpp = options.referenceSpp;
    settings.antialiasedReference = true;   // scored against the pixel-filtered image (docs/sweep.md)
    std::vector<tracer::Frame> frames;
    for (uint32_t i = 0; i < options.qualityFrames; ++i) {
        settings.channels = denoiserChannels();
        if (hasReference(options, i)) settings.channels.push_back(tracer::Channel::Reference);
        frames.push_back(renderer.render(i, settings));
    }
    return frames;
}

std::vector<Image> runChain(const rhi::Device& device, const std::string& name,
                            const std::vector<tracer::Frame>& frames) {
    passes::ChainRunner runner(device, passes::makeChain(name), {frames[0].width, frames[0].height});
    std::vector<Image> displays;
    for (const auto& frame : frames) {
        frames::uploadFrame(runner, frame);
        runner.run();
        displays.push_back(runner.readDisplay());
    }
    return displays;
}

QualityScore score(const std::string& method, const std::vector<Image>& displays,
                   const std::vector<tracer::Frame>& frames, passes::MetricsEvaluator& metrics) {
    QualityScore s{.method = method};
    uint32_t scored = 0;
    for (size_t f = 0; f < frames.size(); ++f) {
        if (!frames[f].has(tracer::Channel::Reference)) continue;
        const auto m = metrics.compare(displays[f], tonemapped(frames[f].get(tracer::Channel::Reference)));
        s.rmse += m.rmse;
        s.psnr += m.psnr;
        s.ssim += m.ssim;
        s.nonFinitePixels += m.nonFinitePixels;
        ++scored;
    }
    if (scored > 0) {
        s.rmse /= scored;
        s.psnr /= scored;
        s.ssim /= scored;
    }
    for (size_t f = 1; f < frames.size(); ++f)
        s.temporal += metrics.temporalError(displays[f], displays[f - 1]) / double(frames.size() - 1);
    return s;
}

} // namespace

std::vector<QualityRow> measureQuality(const rhi::Device& device, const Options& options) {
    if (options.qualityFrames < 2)
        throw Error(ErrorKind::InvalidArgument, "--quality-frames must be at least 2 (temporal error needs a pair)");
    uint32_t references = 0;
    for (uint32_t f = 0; f < options.qualityFrames; ++f) references += hasReference(options, f) ? 1 : 0;
    if (references == 0)
        throw Error(ErrorKind::InvalidArgument, "no --reference-frames below --quality-frames: nothing to score");

    const auto scenes = options.scenes.empty() ? tracer::builtinSceneNames() : options.scenes;
    passes::MetricsEvaluator metrics(device, options.qualitySize);
    std::vector<QualityRow> rows;
    for (size_t i = 0; i < scenes.size(); ++i) {
        const std::string& scene = scenes[i];
        std::printf("[chains] quality %zu/%zu %s: rendering %u frames of %ux%u (%u reference(s) at %u spp) ... ", i + 1,
                    scenes.size(), scene.c_str(), options.qualityFrames, options.qualitySize.width,
                    options.qualitySize.height, references, options.referenceSpp);
        std::fflush(stdout);
        auto start = Clock::now();
        QualityRow row{.scene = scene, .scoredFrames = references};
        const auto frames = renderSequence(scene, options);
        row.renderSeconds = secondsSince(start);
        std::printf("%.1f s\n", row.renderSeconds);

        std::vector<Image> noisy;
        for (const auto& frame : frames) noisy.push_back(tonemapped(frame.get(tracer::Channel::Color)));
        row.scores.push_back(score("noisy", noisy, frames, metrics));
        for (const auto& chain : options.chains) {
            std::printf("[chains] quality %zu/%zu %s: %s ... ", i + 1, scenes.size(), scene.c_str(), chain.c_str());
            std::fflush(stdout);
            start = Clock::now();
            const std::string label = passes::makeChain(chain)->name();
            row.scores.push_back(score(label, runChain(device, chain, frames), frames, metrics));
            const auto& s = row.scores.back();
            std::printf("%.1f s (SSIM %.4f, RMSE %.4f, temporal %.5f)\n", secondsSince(start), s.ssim, s.rmse,
                        s.temporal);
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

} // namespace hush::bench::chain_bench
