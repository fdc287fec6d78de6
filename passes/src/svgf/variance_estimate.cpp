#include <hush/passes/svgf/variance_estimate.hpp>

#include <algorithm>

#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

graph::TextureHandle addSvgfVariancePass(NodeContext& ctx, const std::string& name, const SvgfTemporal& temporal,
                                         const Surface& surface, const SvgfVarianceSettings& settings) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("svgf/variance_estimate");
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    params.set("radius", std::clamp(settings.radius, 0, 16));
    struct Out {
        graph::TextureHandle illumVariance;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("color", temporal.color);
        b.sample("moments", temporal.moments);
        sampleSurface(b, surface);
        o.illumVariance = b.write("illum_variance", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(o.illumVariance).size(), params); };
    });
    return out.illumVariance;
}

} // namespace hush::passes
