#include <hush/passes/svgf/temporal_accumulation.hpp>

#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

SvgfTemporal addSvgfTemporalPass(NodeContext& ctx, const std::string& name, graph::TextureHandle illumination,
                                 graph::TextureHandle reprojection, graph::TextureHandle colorHistory,
                                 const SvgfTemporalSettings& settings) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("svgf/temporal_accumulation");
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    const auto historyValid = params.slot("historyValid", rhi::ScalarType::Uint32);
    return ctx.graph.addPass<SvgfTemporal>(name, [&](graph::PassBuilder& b, SvgfTemporal& o) {
        b.sample("illumination", illumination);
        b.sample("reprojection", reprojection);
        const auto color = b.create(name, fullSize());
        const auto moments = b.create(name + ".moments", fullSize());
        // Without a colour history of the caller's, this pass accumulates its own output.
        b.sample("color_history", colorHistory.valid() ? colorHistory : ctx.graph.history(color));
        b.sample("moments_history", ctx.graph.history(moments));
        o.color = b.write("color", color);
        o.moments = b.write("moments", moments);
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            params.set(historyValid, pc.historyValid() ? 1u : 0u);
            pc.dispatch(pipeline, group, pc.texture(o.color).size(), params);
        };
    });
}

} // namespace hush::passes
