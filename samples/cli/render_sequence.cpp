#include "render_sequence.hpp"

#include <algorithm>
#include <chrono>

#include <hush/tracer/frame_io.hpp>

#include "progress.hpp"

namespace hush::cli {

double renderSequence(const tracer::Renderer& renderer, const SequenceRequest& r) {
    const auto& settings = r.settings;
    auto hasReference = [&](uint32_t i) {
        return settings.referenceSpp && (i - r.first) % r.referenceEvery == r.referenceOffset % r.referenceEvery;
    };
    // Progress in units of paths: a reference frame costs referenceSpp times more.
    auto frameCost = [&](uint32_t i) { return 1.0 + (hasReference(i) ? settings.referenceSpp : 0.0); };
    double totalCost = 0.0, doneCost = 0.0;
    for (uint32_t i = r.first; i < r.first + r.frames; ++i) totalCost += frameCost(i);
    ProgressLine progress("render");
    const auto start = std::chrono::steady_clock::now();
    for (uint32_t i = r.first; i < r.first + r.frames; ++i) {
        tracer::RenderSettings frameSettings = settings;
        std::erase(frameSettings.channels, tracer::Channel::Reference);
        if (hasReference(i)) frameSettings.channels.push_back(tracer::Channel::Reference);
        const std::string detail = "frame " + std::to_string(i - r.first + 1) + "/" + std::to_string(r.frames);
        const double cost = frameCost(i);
        const tracer::Frame frame = renderer.render(i, frameSettings, [&](uint64_t done, uint64_t total) {
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
