#include "sweep_measure.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

#include <hush/core/error.hpp>
#include <hush/core/run_environment.hpp>
#include <hush/passes/chain_file.hpp>
#include <hush/tracer/frame_io.hpp>

#include "progress.hpp"

namespace hush::cli {
namespace {

SweepQuality qualityOf(const ChainResult& c, const std::set<uint32_t>& scheduled) {
    std::vector<passes::ImageMetrics> scored;
    for (const auto& s : c.scored)
        if (scheduled.empty() || scheduled.count(s.frame)) scored.push_back(s.metrics);
    SweepQuality q{.scoredFrames = uint32_t(scored.size())};
    for (const auto& m : scored) {
        q.rmse += m.rmse / scored.size();
        q.relMse += m.relMse / scored.size();
        q.psnr += m.psnr / scored.size();
        q.ssim += m.ssim / scored.size();
    }
    for (double t : c.temporalError) q.temporal += t / c.temporalError.size();
    auto mean = [](const std::vector<double>& v) {
        double sum = 0.0;
        for (double x : v) sum += x;
        return v.empty() ? -1.0 : sum / double(v.size());
    };
    q.ghosting = mean(c.ghosting);
    q.flicker = mean(c.flicker);
    return q;
}

// Frames from the step until the stepped run's RMSE is within 10 % of the steady
// run's (the light doubled from the first frame) on the same frame; both are scored
// on every frame from the step on.
void measureLag(const ChainResult& steady, const ChainResult& stepped, uint32_t stepFrame, SweepQuality& q) {
    std::map<uint32_t, double> baseline;
    for (const auto& s : steady.scored) baseline[s.frame] = s.metrics.rmse;
    q.lagFrames = 0;
    q.lag = -1.0;
    for (const auto& s : stepped.scored) {
        if (s.frame < stepFrame || !baseline.count(s.frame)) continue;
        if (q.lag < 0.0 && s.metrics.rmse <= 1.1 * baseline[s.frame]) q.lag = double(s.frame - stepFrame);
        ++q.lagFrames;
    }
    if (q.lag < 0.0 && q.lagFrames > 0) q.lag = double(q.lagFrames) + 1.0;   // not back within the frames observed
}

} // namespace

std::vector<uint32_t> scoredFrames(const std::vector<std::string>& paths) {
    std::vector<uint32_t> scored;
    for (const auto& path : paths) {
        const auto info = tracer::readFrameInfo(path);
        if (std::find(info.layers.begin(), info.layers.end(), tracer::Channel::Reference) != info.layers.end())
            scored.push_back(frameIndexOf(path));
    }
    return scored;
}

SweepPoint measure(const rhi::Device& device, const SourceFrames& s, const std::string& chainName,
                   const std::string& config, OutputFolder& out, SweepQuality& noisy, bool writeImages) {
    DenoiseJobOptions job{.chains = {chainName}, .framePaths = s.paths, .writeExr = false, .writePng = writeImages};
    job.outputPrefix = "runs/" + s.source.key;
    job.exposure = float(s.source.exposure);
    job.pngScoredOnly = job.quiet = true;
    job.writeReferencePng = writeImages;
    const auto before = core::sampleCpuTimes();
    const auto result = runDenoiseJob(device, job, out);
    const auto& chain = result.chains.at(1);
    noisy = qualityOf(result.chains.at(0), s.scheduled);
    SweepPoint point{.source = s.source.key, .config = config, .gpuMs = median(chain.frameMs),
                     .otherCpuShare = core::otherCpuShare(before, core::sampleCpuTimes()),
                     .deviceBytes = chain.transientBytes + chain.historyBytes,
                     .quality = qualityOf(chain, s.scheduled), .nonFiniteOutputs = chain.nonFiniteOutputs};
    if (s.stepFrame != ~0u) {
        // The light doubled from the step on, against the light doubled throughout (the
        // steady state the stepped run should reach); no images written.
        job.stepExposure = 2.0f;
        job.writePng = job.writeReferencePng = false;
        job.stepFrame = 0;
        const auto doubled = runDenoiseJob(device, job, out);
        job.stepFrame = s.stepFrame;
        const auto stepped = runDenoiseJob(device, job, out);
        measureLag(doubled.chains.at(1), stepped.chains.at(1), s.stepFrame, point.quality);
    }
    return point;
}


SweepResult quickSweep(const rhi::Device& device, const std::vector<std::string>& framePaths, OutputFolder& out) {
    if (scoredFrames(framePaths).empty())
        throw Error(ErrorKind::InvalidArgument, "--budget-ms without --sweep measures the chains on the frames, so "
                                                "some frames must carry a 'reference' layer; give --sweep <sweep.json> "
                                                "from hush sweep instead");
    SweepResult result;
    const auto info = tracer::readFrameInfo(framePaths.front());
    SourceFrames s{.paths = framePaths};
    s.source = {.key = "frames", .description = "the input frames", .width = info.width, .height = info.height,
                .frames = uint32_t(framePaths.size()), .family = "frames"};
    result.sources.push_back(s.source);
    ProgressLine progress("budget");
    const auto chains = passes::builtinChainNames();
    for (size_t i = 0; i < chains.size(); ++i) {
        result.configs.push_back({.chain = chains[i], .name = chains[i], .label = chains[i] + " (its defaults)"});
        result.points.push_back(measure(device, s, chains[i], chains[i], out, result.sources.back().noisy, false));
        progress.update(double(i + 1) / double(chains.size()), "measured " + chains[i]);
    }
    progress.finish("measured " + std::to_string(chains.size()) + " chains on the frames");
    return result;
}

} // namespace hush::cli
