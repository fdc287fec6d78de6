#include <hush/passes/svgf/variance_estimate.hpp>

#include <algorithm>

#include <hush/passes/common/normal_power.hpp>
#include <hush/passes/common/tile_list.hpp>
#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

namespace {
// Pixels per invocation along x: the shader's kRow; a tile is 8 x 8 invocations.
constexpr uint32_t kVarianceRow = 4;
constexpr rhi::Extent2D kVarianceTile{8 * kVarianceRow, 8};

rhi::ComputePipeline variancePipeline(NodeContext& ctx, const char* shader, const SvgfVarianceSettings& settings) {
    return ctx.pipelines.get(shader, {normalPowerConstant("wholeSigmaN", settings.sigmaN),
                                      {"radius", double(std::clamp(settings.radius, 0, 16))}});
}

struct Classified {
    graph::TextureHandle illumVariance;
    graph::BufferHandle tiles;
};

// "<name>.spatial": every pixel of the tiles "<name>" listed, the 7x7 estimate where
// the history is short (passes/common/tile_list.hpp).
graph::TextureHandle addSpatialPass(NodeContext& ctx, const std::string& name, const SvgfTemporal& temporal,
                                    const Surface& surface, const Classified& classified,
                                    const SvgfVarianceSettings& settings) {
    const rhi::ComputePipeline pipeline = variancePipeline(ctx, "svgf/variance_spatial", settings);
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    struct Out {
        graph::TextureHandle illumVariance;
    };
    const auto out = ctx.graph.addPass<Out>(name + ".spatial", [&](graph::PassBuilder& b, Out& o) {
        b.sample("color", temporal.color);
        b.sample("moments", temporal.moments);
        sampleSurface(b, surface);
        const auto tiles = b.readIndirect("tiles", classified.tiles);
        o.illumVariance = b.readWrite("illum_variance", classified.illumVariance);
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) { pc.dispatchIndirect(pipeline, group, tiles, params); };
    });
    return out.illumVariance;
}
} // namespace

graph::TextureHandle addSvgfVariancePass(NodeContext& ctx, const std::string& name, const SvgfTemporal& temporal,
                                         const Surface& surface, const SvgfVarianceSettings& settings) {
    const graph::BufferHandle tiles = addTileListPass(ctx, name + ".tiles", kVarianceTile);
    const rhi::ComputePipeline pipeline = variancePipeline(ctx, "svgf/variance_estimate", settings);
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    const auto classified = ctx.graph.addPass<Classified>(name, [&](graph::PassBuilder& b, Classified& o) {
        b.sample("color", temporal.color);
        b.sample("moments", temporal.moments);
        sampleSurface(b, surface);
        o.tiles = b.readWrite("tiles", tiles);
        o.illumVariance = b.write("illum_variance", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) {
            const rhi::Extent2D size = pc.texture(o.illumVariance).size();
            pc.dispatch(pipeline, group, {(size.width + kVarianceRow - 1) / kVarianceRow, size.height}, params);
        };
    });
    return addSpatialPass(ctx, name, temporal, surface, classified, settings);
}

} // namespace hush::passes
