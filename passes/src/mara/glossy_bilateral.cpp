#include <hush/passes/mara/glossy_bilateral.hpp>

#include <hush/passes/common/normal_power.hpp>
#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

namespace {
graph::TextureHandle addDirection(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                  graph::TextureHandle roughness, const Surface& surface, graph::TextureHandle position,
                                  const MaraGlossyBilateralSettings& settings, bool vertical) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("mara/glossy_bilateral", {normalPowerConstant("wholeNormalPower", settings.normalPower)});
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    params.set("vertical", vertical);
    struct Out {
        graph::TextureHandle filtered;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("color", color);
        b.sample("roughness", roughness);
        b.sample("normal_depth", surface.normalDepth);
        b.sample("position", position);
        o.filtered = b.write("filtered", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(o.filtered).size(), params); };
    });
    return out.filtered;
}
} // namespace

graph::TextureHandle addMaraGlossyBilateralPasses(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                                  graph::TextureHandle roughness, const Surface& surface,
                                                  graph::TextureHandle position,
                                                  const MaraGlossyBilateralSettings& settings) {
    const auto horizontal =
        addDirection(ctx, name + ".horizontal", color, roughness, surface, position, settings, false);
    return addDirection(ctx, name + ".vertical", horizontal, roughness, surface, position, settings, true);
}

} // namespace hush::passes
