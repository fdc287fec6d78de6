#include <hush/passes/mara/glossy_bilateral.hpp>

#include <hush/passes/common/normal_power.hpp>
#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

namespace {
constexpr uint32_t kGlossyRow = 4;   // pixels per invocation along the axis: kRow in shaders/mara/glossy_bilateral.comp

// One invocation per kGlossyRow pixels along the blur's axis.
rhi::Extent2D rowThreads(rhi::Extent2D size, bool vertical) {
    const auto rows = [](uint32_t n) { return (n + kGlossyRow - 1) / kGlossyRow; };
    return vertical ? rhi::Extent2D{size.width, rows(size.height)} : rhi::Extent2D{rows(size.width), size.height};
}

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
        return [=](graph::PassContext& pc) {
            pc.dispatch(pipeline, group, rowThreads(pc.texture(o.filtered).size(), vertical), params);
        };
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
