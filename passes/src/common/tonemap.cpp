#include <hush/passes/common/tonemap.hpp>

#include <algorithm>

#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

namespace {
// Narkowicz's fit reaches 1 at x ~ 7.24 ((a - c) x^2 + (b - d) x - e = 0) and stays
// above it, so clamping x to 64 first changes nothing and keeps x^2 finite. Its
// denominator has no real root (d^2 < 4 c e), so it never divides by zero.
constexpr float kAcesInputMax = 64.0f;
// x / (1 + x) rounds to 1 in fp32 far below this; the clamp keeps luminance finite.
constexpr float kReinhardInputMax = 1e30f;
} // namespace

float tonemapAcesFit(float x) {
    constexpr float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
    x = std::min(std::max(x, 0.0f), kAcesInputMax);
    const float y = (x * (a * x + b)) / (x * (c * x + d) + e);
    return std::min(std::max(y, 0.0f), 1.0f);
}

float tonemapReinhard(float x) {
    x = std::min(std::max(x, 0.0f), kReinhardInputMax);
    return x / (1.0f + x);
}

float tonemapLuminance(const float rgb[3]) { return 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2]; }

void tonemap(const TonemapSettings& settings, float rgb[3]) {
    for (int c = 0; c < 3; ++c) rgb[c] *= settings.exposure;
    switch (settings.op) {
    case TonemapOperator::AcesFit:
        for (int c = 0; c < 3; ++c) rgb[c] = tonemapAcesFit(rgb[c]);
        return;
    case TonemapOperator::ReinhardPerChannel:
        for (int c = 0; c < 3; ++c) rgb[c] = tonemapReinhard(rgb[c]);
        return;
    case TonemapOperator::ReinhardLuminance: {
        for (int c = 0; c < 3; ++c) rgb[c] = std::min(std::max(rgb[c], 0.0f), kReinhardInputMax);
        // L_d / L = 1 / (1 + L): the colour keeps its chromaticity, no division by L.
        const float scale = 1.0f + tonemapLuminance(rgb);
        for (int c = 0; c < 3; ++c) rgb[c] = std::min(rgb[c] / scale, 1.0f);
        return;
    }
    }
}

graph::TextureHandle addTonemapPass(NodeContext& ctx, const std::string& name, graph::TextureHandle radiance,
                                    const TonemapSettings& settings) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("common/tonemap");
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    struct Out {
        graph::TextureHandle display;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("radiance", radiance);
        o.display = b.write("display", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(o.display).size(), params); };
    });
    return out.display;
}

} // namespace hush::passes
