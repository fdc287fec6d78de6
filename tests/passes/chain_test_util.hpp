#pragma once
// Shared pieces of the chain tests: a small tracer sequence rendered once per test
// process, feeding a ChainRunner from tracer frames (optionally altered), and the
// display-space images the metrics compare.
#include <functional>
#include <memory>
#include <vector>

#include <hush/passes/chain_runner.hpp>
#include <hush/passes/metrics/metrics_evaluator.hpp>
#include <hush/tracer/frame.hpp>

#include "frame_upload.hpp"

namespace hush::passes_test {

// The built-in cornell scene's camera path, 96x96, 16 frames, 1 bounce; every frame
// has color, direct, indirect, albedo, normal, position, depth, motion and meshid;
// frames 7, 11 and 15 a 256-spp reference. Rendered on first use.
const std::vector<tracer::Frame>& cornellSequence();
// The same path at 128x128 (BMFR's 32-pixel blocks need room: Sec. 6.1 sizes them for 720p).
const std::vector<tracer::Frame>& cornellSequence128();

// A built-in scene's camera path at size x size, 16 frames, 1 bounce, with every layer
// (Mara et al.'s matte, glossy and virtual positions, and their low-noise direct
// light, included); frames 7, 11 and 15 have a 128-spp reference. Rendered on first
// use, once per scene and size.
const std::vector<tracer::Frame>& sceneSequence(const std::string& scene, uint32_t size);

// As hush-bench-chains' quality part renders it (and hush sweep, hush demo): every
// layer, 16 frames, a 256-spp anti-aliased reference (RenderSettings::
// antialiasedReference) on frames 7 and 15. Rendered on first use.
const std::vector<tracer::Frame>& benchSequence(const std::string& scene, uint32_t size);

// Called with each channel's pixels before upload, to inject faults.
using ChannelEdit = frames::ChannelEdit;
void uploadFrame(passes::ChainRunner& runner, const tracer::Frame& frame, const ChannelEdit& edit = {});

// Runs `chain` over `frames`, returning each frame's display image (RGBA).
std::vector<std::vector<float>> runSequence(std::unique_ptr<passes::Chain> chain,
                                            const std::vector<tracer::Frame>& frames,
                                            const std::function<ChannelEdit(size_t frame)>& edits = {});

// Marks the end-of-frame value of every history's source as an output (before the
// first frame), so that tests can read what the next frame's histories will hold.
std::vector<graph::TextureHandle> markHistorySources(graph::RenderGraph& graph);

// A tracer image (3 channels) tonemapped with the default TonemapSettings, as RGBA.
std::vector<float> tonemappedRgba(const tracer::Image& hdr);
// Mean |a - b| over RGB, divided by the mean |b| (0 when b is black).
double relativeL1(const std::vector<float>& a, const std::vector<float>& b);
size_t nonFinite(const std::vector<float>& values);

// A chain's quality over a sequence: mean RMSE and SSIM of the tonemapped images over
// the frames with a reference, and the mean temporal error between consecutive frames.
struct Score {
    double rmse = 0.0, ssim = 0.0, temporal = 0.0;
};
Score score(const std::vector<std::vector<float>>& displays, const std::vector<tracer::Frame>& frames,
            passes::MetricsEvaluator& metrics);
// The noisy input's score, tonemapped like the chains' display output.
Score noisyScore(const std::vector<tracer::Frame>& frames, passes::MetricsEvaluator& metrics);

} // namespace hush::passes_test
