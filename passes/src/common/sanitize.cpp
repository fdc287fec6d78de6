#include <hush/passes/common/sanitize.hpp>

#include <limits>

namespace hush::passes {

namespace {
struct SanitizeParams {
    uint32_t slot;
    float lo, hi, replacement;
};

const char* shaderFor(rhi::Format format) {
    switch (format) {
    case rhi::Format::R32Float: return "common/sanitize_r32f";
    case rhi::Format::RG32Float: return "common/sanitize_rg32f";
    default: return "common/sanitize_rgba32f";
    }
}
} // namespace

SanitizeRange sanitizeRange(InputChannel channel, const SanitizeSettings& settings) {
    constexpr float big = std::numeric_limits<float>::max();
    switch (channel) {
    case InputChannel::Color:
    case InputChannel::Direct:
    case InputChannel::Indirect:
    case InputChannel::Emission: return {0.0f, settings.maxRadiance, 0.0f};
    case InputChannel::Albedo:
    case InputChannel::Specular: return {0.0f, 1.0f, 0.0f};
    case InputChannel::Normal: return {-1.0f, 1.0f, 0.0f};
    case InputChannel::Depth:
    case InputChannel::Roughness: return {0.0f, big, 0.0f};
    case InputChannel::MeshId: return {-1.0f, big, -1.0f};
    case InputChannel::Position:
    case InputChannel::Motion: return {-big, big, 0.0f};
    }
    return {-big, big, 0.0f};
}

SanitizedInputs addSanitizePass(NodeContext& ctx, const std::string& name, const DenoiseInputs& inputs,
                                const SanitizeSettings& settings) {
    SanitizedInputs out;
    const rhi::ComputePipeline clear = ctx.pipelines.get("common/clear_counters");
    ctx.graph.addPass(name + ".clear", [&](graph::PassBuilder& b) {
        auto counts = b.write("counts", b.create(name + ".counts", graph::BufferInfo{kInputChannelCount * 4}));
        auto group = b.bindGroup(clear, 0, {{.name = "Counters", .buffer = counts}});
        out.counts = counts;
        return [=](graph::PassContext& pc) {
            pc.dispatch(clear, group, {uint32_t(kInputChannelCount), 1}, uint32_t(kInputChannelCount));
        };
    });
    for (const auto& info : allInputChannels()) {
        if (!inputs.has(info.channel)) continue;
        const std::string stage = name + "." + std::string(info.name);
        const rhi::ComputePipeline pipeline = ctx.pipelines.get(shaderFor(info.format));
        const auto range = sanitizeRange(info.channel, settings);
        const SanitizeParams params{uint32_t(info.channel), range.lo, range.hi, range.replacement};
        ctx.graph.addPass(stage, [&](graph::PassBuilder& b) {
            auto src = b.sample("src", inputs[info.channel], {.format = info.format});
            auto dst = b.write("dst", b.create(stage, fullSize(info.format)));
            out.counts = b.readWrite("counts", out.counts);
            auto group = b.bindGroup(pipeline, 0,
                                     {{.name = "src", .texture = src},
                                      {.name = "dst", .texture = dst},
                                      {.name = "Counters", .buffer = out.counts}});
            out.inputs[info.channel] = dst;
            return [=](graph::PassContext& pc) {
                pc.dispatch(pipeline, group, pc.texture(dst).size(), params);
            };
        });
    }
    ctx.graph.markOutput(out.counts);
    return out;
}

} // namespace hush::passes
