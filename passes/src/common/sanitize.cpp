#include <hush/passes/common/sanitize.hpp>

#include <limits>

namespace hush::passes {

namespace {
constexpr uint32_t kSanitizeRow = 4;   // pixels per invocation along x: kRow in shaders/common/sanitize.glsl

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
    case InputChannel::Emission:
    case InputChannel::Matte:
    case InputChannel::Glossy: return {0.0f, settings.maxRadiance, 0.0f};
    case InputChannel::Albedo:
    case InputChannel::Specular: return {0.0f, 1.0f, 0.0f};
    case InputChannel::Normal: return {-1.0f, 1.0f, 0.0f};
    case InputChannel::Depth:
    case InputChannel::Roughness: return {0.0f, big, 0.0f};
    case InputChannel::MeshId: return {-1.0f, big, -1.0f};
    case InputChannel::Position:
    case InputChannel::VirtualPos:
    case InputChannel::Motion: return {-big, big, 0.0f};
    }
    return {-big, big, 0.0f};
}

namespace {
graph::BufferHandle addClearCountsPass(NodeContext& ctx, const std::string& name) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("common/clear_counters");
    rhi::PushConstants params(pipeline);
    params.set("count", uint32_t(kInputChannelCount));
    struct Out {
        graph::BufferHandle counts;
    };
    const auto out = ctx.graph.addPass<Out>(name + ".clear", [&](graph::PassBuilder& b, Out& o) {
        o.counts = b.write("counts", b.create(name + ".counts", graph::BufferInfo{kInputChannelCount * 4}));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, {uint32_t(kInputChannelCount), 1}, params); };
    });
    return out.counts;
}
} // namespace

SanitizedInputs addSanitizePass(NodeContext& ctx, const std::string& name, const DenoiseInputs& inputs,
                                const SanitizeSettings& settings) {
    SanitizedInputs out;
    out.counts = addClearCountsPass(ctx, name);
    for (const auto& info : allInputChannels()) {
        if (!inputs.has(info.channel)) continue;
        const std::string stage = name + "." + std::string(info.name);
        const rhi::ComputePipeline pipeline = ctx.pipelines.get(shaderFor(info.format));
        const auto range = sanitizeRange(info.channel, settings);
        rhi::PushConstants params(pipeline);
        params.set("slot", uint32_t(info.channel)).set("lo", range.lo).set("hi", range.hi).set("replacement", range.replacement);
        struct Stage {
            graph::TextureHandle sanitized;
            graph::BufferHandle counts;
        };
        const auto stageOut = ctx.graph.addPass<Stage>(stage, [&](graph::PassBuilder& b, Stage& o) {
            b.sample("src", inputs[info.channel], {.format = info.format});
            o.sanitized = b.write("dst", b.create(stage, fullSize(info.format)));
            o.counts = b.readWrite("counts", out.counts);
            const auto group = b.bindGroup(pipeline);
            return [=](graph::PassContext& pc) {
                const rhi::Extent2D size = pc.texture(o.sanitized).size();
                pc.dispatch(pipeline, group, {(size.width + kSanitizeRow - 1) / kSanitizeRow, size.height}, params);
            };
        });
        out.inputs[info.channel] = stageOut.sanitized;
        out.counts = stageOut.counts;
    }
    ctx.graph.markOutput(out.counts);
    return out;
}

} // namespace hush::passes
