#include "render_sequence.hpp"

#include <algorithm>
#include <chrono>

#include <hush/core/error.hpp>
#include <hush/core/run_environment.hpp>
#include <hush/tracer/frame_io.hpp>

#include "progress.hpp"

namespace hush::cli {

namespace {

// A frame lives in memory as floats, and once more as the EXR writer's copy: refuse a
// size that cannot fit before allocating it, saying what it needs.
void checkHostMemory(const tracer::RenderSettings& settings) {
    uint64_t components = 0;
    for (const auto c : settings.channels) components += tracer::channelInfo(c).components;
    components += tracer::channelInfo(tracer::Channel::Reference).components;
    const uint64_t bytes = 2 * uint64_t(settings.width) * settings.height * components * sizeof(float);
    const uint64_t available = core::availableHostMemory();
    if (available && bytes > available)
        throw Error(ErrorKind::OutOfMemory,
                    "a " + std::to_string(settings.width) + "x" + std::to_string(settings.height) + " frame with " +
                        std::to_string(settings.channels.size()) + " layers needs about " +
                        std::to_string(bytes >> 20) + " MiB of host memory, " + std::to_string(available >> 20) +
                        " MiB are available; render a smaller --size or fewer --channels");
}

} // namespace

double renderSequence(const tracer::Renderer& renderer, const SequenceRequest& r) {
    const auto& settings = r.settings;
    checkHostMemory(settings);
    auto scored = [&](uint32_t i) { return (i - r.first) % r.referenceEvery == r.referenceOffset % r.referenceEvery; };
    auto hasReference = [&](uint32_t i) {
        return settings.referenceSpp && (scored(i) || i >= r.referencesFrom ||
                                         (r.referencePairs && i + 1 < r.first + r.frames && scored(i + 1)));
    };
    // Progress in units of paths: a reference frame costs referenceSpp times more.
    auto frameCost = [&](uint32_t i) { return 1.0 + (hasReference(i) ? settings.referenceSpp : 0.0); };
    double totalCost = 0.0, doneCost = 0.0;
    for (uint32_t i = r.first; i < r.first + r.frames; ++i) totalCost += frameCost(i);
    ProgressLine progress("render");
    const auto start = std::chrono::steady_clock::now();
    tracer::Frame frame;   // one for the sequence: its images are allocated once
    for (uint32_t i = r.first; i < r.first + r.frames; ++i) {
        tracer::RenderSettings frameSettings = settings;
        std::erase(frameSettings.channels, tracer::Channel::Reference);
        if (hasReference(i)) frameSettings.channels.push_back(tracer::Channel::Reference);
        const std::string detail = "frame " + std::to_string(i - r.first + 1) + "/" + std::to_string(r.frames);
        const double cost = frameCost(i);
        renderer.renderInto(frame, i, frameSettings, [&](uint64_t done, uint64_t total) {
            progress.update((doneCost + cost * double(done) / double(total)) / totalCost, detail);
        });
        tracer::writeFrame(frame, tracer::framePath(r.outFolder, i));
        doneCost += cost;
        progress.update(doneCost / totalCost, detail);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char summary[200];
    std::snprintf(summary, sizeof summary, "done: %u frames in %s, %.2f Mrays/s, written to %s", r.frames,
                  formatSeconds(seconds).c_str(), double(renderer.raysTraced()) / seconds * 1e-6, r.outFolder.c_str());
    progress.finish(summary);
    return seconds;
}

} // namespace hush::cli
