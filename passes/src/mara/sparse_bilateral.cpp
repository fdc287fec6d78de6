#include <hush/passes/mara/sparse_bilateral.hpp>

#include <hush/passes/common/normal_power.hpp>
#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

graph::TextureHandle addMaraSparseBilateralPass(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                                const Surface& surface, graph::TextureHandle position,
                                                graph::TextureHandle radius,
                                                const MaraSparseBilateralSettings& settings) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("mara/sparse_bilateral", {normalPowerConstant("wholeNormalPower", settings.normalPower)});
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    params.set("useRadiusMap", radius.valid());
    const auto radiusPixels = params.slot("radiusPixels", rhi::ScalarType::Float32);
    const auto frame = params.slot("frame", rhi::ScalarType::Uint32);
    const float diameter = settings.diameter;
    struct Out {
        graph::TextureHandle filtered;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("color", color);
        b.sample("normal_depth", surface.normalDepth);
        b.sample("position", position);
        b.sample("radius", radius, {.optional = true});
        o.filtered = b.write("filtered", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            const auto size = pc.texture(o.filtered).size();
            params.set(radiusPixels, 0.5f * diameter * float(size.width));
            params.set(frame, uint32_t(pc.historyFrame()));
            pc.dispatch(pipeline, group, size, params);
        };
    });
    return out.filtered;
}

} // namespace hush::passes
