#include "soak.hpp"

#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <unistd.h>

#include <hush/core/error.hpp>
#include <hush/passes/chain_file.hpp>
#include <hush/passes/chain_runner.hpp>
#include <hush/tracer/builtin_scenes.hpp>
#include <hush/tracer/renderer.hpp>

#include "frame_upload.hpp"

namespace hush::soak {

namespace {

std::vector<tracer::Frame> renderSequence(const std::string& scene, rhi::Extent2D size, uint32_t count) {
    const tracer::Renderer renderer(tracer::makeBuiltinScene(scene));
    tracer::RenderSettings settings;
    settings.width = size.width;
    settings.height = size.height;
    settings.referenceSpp = 0;
    for (const auto channel : tracer::kAllChannels)
        if (channel != tracer::Channel::Reference) settings.channels.push_back(channel);
    std::vector<tracer::Frame> frames;
    for (uint32_t i = 0; i < count; ++i) frames.push_back(renderer.render(i, settings));
    return frames;
}

// Least-squares slope of y over x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() < 2) return 0.0;
    double mx = 0, my = 0;
    for (size_t i = 0; i < x.size(); ++i) mx += x[i], my += y[i];
    mx /= double(x.size());
    my /= double(y.size());
    double sxy = 0, sxx = 0;
    for (size_t i = 0; i < x.size(); ++i) sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
    return sxx > 0 ? sxy / sxx : 0.0;
}

// Growth per 1,000 frames of `field`, fitted per size (the footprint differs by size)
// and averaged over the sizes with two samples or more. Each size's first sample is
// left out: a first segment also fills caches that are kept (the driver's compiled
// shaders, the allocator's arenas), which is warm-up, not a leak.
template <class Field>
double growthPer1000(const std::vector<SoakSample>& samples, Field field) {
    std::map<std::pair<uint32_t, uint32_t>, std::pair<std::vector<double>, std::vector<double>>> bySize;
    std::map<std::pair<uint32_t, uint32_t>, bool> seen;
    for (const auto& s : samples) {
        if (!seen[{s.size.width, s.size.height}]) {
            seen[{s.size.width, s.size.height}] = true;
            continue;
        }
        auto& [x, y] = bySize[{s.size.width, s.size.height}];
        x.push_back(double(s.frame) / 1000.0);
        y.push_back(double(field(s)));
    }
    double sum = 0;
    int fitted = 0;
    for (const auto& [size, xy] : bySize)
        if (xy.first.size() >= 2) sum += slope(xy.first, xy.second), ++fitted;
    return fitted ? sum / fitted : 0.0;
}

} // namespace

uint64_t residentBytes() {
    std::ifstream statm("/proc/self/statm");
    uint64_t size = 0, resident = 0;
    if (!(statm >> size >> resident)) return 0;
    return resident * uint64_t(::sysconf(_SC_PAGESIZE));
}

SoakResult runSoak(const rhi::Device& device, const SoakPlan& plan, const std::function<void(const SoakSample&)>& onSample) {
    if (plan.segmentFrames == 0 || plan.sizes.empty() || plan.scenes.empty() || plan.sequenceFrames == 0)
        throw Error(ErrorKind::InvalidArgument, "soak: segmentFrames, sizes, scenes and sequenceFrames must be non-empty");
    std::map<std::pair<std::string, std::pair<uint32_t, uint32_t>>, std::vector<tracer::Frame>> sequences;
    SoakResult result;
    for (uint32_t done = 0, segment = 0; done < plan.frames; ++segment) {
        const rhi::Extent2D size = plan.sizes[segment % plan.sizes.size()];
        const std::string& scene = plan.scenes[segment % plan.scenes.size()];
        auto& frames = sequences[{scene, {size.width, size.height}}];
        if (frames.empty()) frames = renderSequence(scene, size, plan.sequenceFrames);
        const uint32_t count = std::min(plan.segmentFrames, plan.frames - done);
        SoakSample sample{.size = size, .scene = scene};
        const auto start = std::chrono::steady_clock::now();
        {
            passes::ChainRunner runner(device, passes::makeChain(plan.chain), size, {},
                                       frames::channelsOf(frames.front()));
            for (uint32_t f = 0; f < count; ++f) {
                frames::uploadFrame(runner, frames[f % frames.size()]);
                runner.run();
                sample.nonFinite += frames::countNonFinite(runner.readDisplay());
            }
            // Sampled while the runner is alive: its footprint is part of what must not grow.
            done += count;
            sample.frame = done;
            sample.residentBytes = residentBytes();
            sample.deviceBytes = device.allocatedBytes();
            sample.liveObjects = rhi::liveObjects().total();
        }
        sample.msPerFrame = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / count;
        if (onSample) onSample(sample);
        result.samples.push_back(sample);
    }
    result.residentBytesPer1000 = growthPer1000(result.samples, [](const SoakSample& s) { return s.residentBytes; });
    result.deviceBytesPer1000 = growthPer1000(result.samples, [](const SoakSample& s) { return s.deviceBytes; });
    result.liveObjectsPer1000 = growthPer1000(result.samples, [](const SoakSample& s) { return s.liveObjects; });
    return result;
}

} // namespace hush::soak
