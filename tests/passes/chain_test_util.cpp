#include "chain_test_util.hpp"

#include "frame_upload.hpp"

#include <cmath>
#include <algorithm>
#include <map>
#include <tuple>

#include <hush/passes/common/tonemap.hpp>
#include <hush/tracer/builtin_scenes.hpp>
#include <hush/tracer/renderer.hpp>

#include "support/gpu_context.hpp"

namespace hush::passes_test {

namespace {
std::vector<tracer::Frame> renderCornell(uint32_t size) {
    const tracer::Renderer renderer(tracer::makeBuiltinScene("cornell"));
    tracer::RenderSettings settings;
    settings.width = settings.height = size;
    settings.referenceSpp = 256;
    std::vector<tracer::Frame> out;
    for (uint32_t i = 0; i < 16; ++i) {
        settings.channels = {tracer::Channel::Color,    tracer::Channel::Direct, tracer::Channel::Indirect,
                             tracer::Channel::Albedo,   tracer::Channel::Normal, tracer::Channel::Position,
                             tracer::Channel::Depth,    tracer::Channel::Motion, tracer::Channel::MeshId,
                             tracer::Channel::Emission};
        if (i == 7 || i == 11 || i == 15) settings.channels.push_back(tracer::Channel::Reference);
        out.push_back(renderer.render(i, settings));
    }
    return out;
}
} // namespace

namespace {
// 16 frames of a built-in scene's path with every layer, a reference on `scored`;
// rendered once per (scene, size, kind) in this process.
const std::vector<tracer::Frame>& cachedSequence(const std::string& scene, uint32_t size, uint32_t referenceSpp,
                                                 bool antialiased, std::initializer_list<uint32_t> scored) {
    static std::map<std::tuple<std::string, uint32_t, bool>, std::vector<tracer::Frame>> cache;
    auto& frames = cache[{scene, size, antialiased}];
    if (!frames.empty()) return frames;
    const tracer::Renderer renderer(tracer::makeBuiltinScene(scene));
    tracer::RenderSettings settings;
    settings.width = settings.height = size;
    settings.referenceSpp = referenceSpp;
    settings.antialiasedReference = antialiased;
    for (uint32_t i = 0; i < 16; ++i) {
        settings.channels.clear();
        for (const auto channel : tracer::kAllChannels)
            if (channel != tracer::Channel::Reference) settings.channels.push_back(channel);
        if (std::find(scored.begin(), scored.end(), i) != scored.end())
            settings.channels.push_back(tracer::Channel::Reference);
        frames.push_back(renderer.render(i, settings));
    }
    return frames;
}
} // namespace

const std::vector<tracer::Frame>& sceneSequence(const std::string& scene, uint32_t size) {
    return cachedSequence(scene, size, 128, false, {7, 11, 15});
}

const std::vector<tracer::Frame>& benchSequence(const std::string& scene, uint32_t size) {
    return cachedSequence(scene, size, 256, true, {7, 15});
}

const std::vector<tracer::Frame>& cornellSequence() {
    static const std::vector<tracer::Frame> frames = renderCornell(96);
    return frames;
}

const std::vector<tracer::Frame>& cornellSequence128() {
    static const std::vector<tracer::Frame> frames = renderCornell(128);
    return frames;
}

void uploadFrame(passes::ChainRunner& runner, const tracer::Frame& frame, const ChannelEdit& edit) {
    frames::uploadFrame(runner, frame, edit);
}

std::vector<std::vector<float>> runSequence(std::unique_ptr<passes::Chain> chain,
                                            const std::vector<tracer::Frame>& frames,
                                            const std::function<ChannelEdit(size_t)>& edits) {
    passes::ChainRunner runner(test::gpu().device, std::move(chain), {frames[0].width, frames[0].height});
    std::vector<std::vector<float>> displays;
    for (size_t f = 0; f < frames.size(); ++f) {
        uploadFrame(runner, frames[f], edits ? edits(f) : ChannelEdit{});
        runner.run();
        displays.push_back(runner.readDisplay());
    }
    return displays;
}

std::vector<graph::TextureHandle> markHistorySources(graph::RenderGraph& graph) {
    std::vector<graph::TextureHandle> sources;
    const auto& model = graph.model();
    for (uint32_t r = 0; r < model.resources.size(); ++r) {
        if (model.resources[r].origin != graph::ResourceOrigin::History) continue;
        if (const auto source = graph.historySource({r, 0}); source.valid()) sources.push_back(source);
    }
    for (auto h : sources) graph.markOutput(h);
    return sources;
}

std::vector<float> tonemappedRgba(const tracer::Image& hdr) {
    std::vector<float> out(size_t(hdr.width) * hdr.height * 4, 1.0f);
    const passes::TonemapSettings settings;
    for (size_t i = 0; i < size_t(hdr.width) * hdr.height; ++i) {
        for (size_t c = 0; c < 3; ++c) out[i * 4 + c] = hdr.pixels[i * hdr.channels + c];
        passes::tonemap(settings, &out[i * 4]);
    }
    return out;
}

double relativeL1(const std::vector<float>& a, const std::vector<float>& b) {
    double diff = 0.0, norm = 0.0;
    for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
        if (i % 4 == 3) continue;
        diff += std::fabs(double(a[i]) - double(b[i]));
        norm += std::fabs(double(b[i]));
    }
    return norm > 0.0 ? diff / norm : diff;
}

size_t nonFinite(const std::vector<float>& values) { return size_t(frames::countNonFinite(values)); }

Score score(const std::vector<std::vector<float>>& displays, const std::vector<tracer::Frame>& frames,
            passes::MetricsEvaluator& metrics) {
    Score s;
    int scored = 0;
    for (size_t f = 0; f < frames.size(); ++f) {
        if (f > 0) s.temporal += metrics.temporalError(displays[f], displays[f - 1]) / double(frames.size() - 1);
        if (!frames[f].has(tracer::Channel::Reference)) continue;
        const auto m = metrics.compare(displays[f], tonemappedRgba(frames[f].get(tracer::Channel::Reference)));
        s.rmse += m.rmse;
        s.ssim += m.ssim;
        ++scored;
    }
    s.rmse /= scored;
    s.ssim /= scored;
    return s;
}

Score noisyScore(const std::vector<tracer::Frame>& frames, passes::MetricsEvaluator& metrics) {
    std::vector<std::vector<float>> noisy;
    for (const auto& f : frames) noisy.push_back(tonemappedRgba(f.get(tracer::Channel::Color)));
    return score(noisy, frames, metrics);
}

} // namespace hush::passes_test
