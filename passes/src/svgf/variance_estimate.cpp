#include <hush/passes/svgf/variance_estimate.hpp>

#include <algorithm>

#include <hush/passes/common/normal_power.hpp>
#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

namespace {
// Pixels per invocation along x: the shader's kRow.
constexpr uint32_t kVarianceRow = 4;
} // namespace

graph::TextureHandle addSvgfVariancePass(NodeContext& ctx, const std::string& name, const SvgfTemporal& temporal,
                                         const Surface& surface, const SvgfVarianceSettings& settings) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get(
        "svgf/variance_estimate",
        {normalPowerConstant("wholeSigmaN", settings.sigmaN), {"radius", double(std::clamp(settings.radius, 0, 16))}});
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    struct Out {
        graph::TextureHandle illumVariance;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("color", temporal.color);
        b.sample("moments", temporal.moments);
        sampleSurface(b, surface);
        o.illumVariance = b.write("illum_variance", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) {
            const rhi::Extent2D size = pc.texture(o.illumVariance).size();
            pc.dispatch(pipeline, group, {(size.width + kVarianceRow - 1) / kVarianceRow, size.height}, params);
        };
    });
    return out.illumVariance;
}

} // namespace hush::passes
