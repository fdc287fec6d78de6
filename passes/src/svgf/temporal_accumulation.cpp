#include <hush/passes/svgf/temporal_accumulation.hpp>

#include <hush/passes/common/reproject.hpp>
#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

namespace {

struct Histories {
    graph::TextureHandle color, moments;
};

// "<name>.fallback": every pixel of the tiles where the reprojection ran its 3x3
// fallback, every footprint (shaders/common/footprint_tiles.glsl).
SvgfTemporal addFallbackPass(NodeContext& ctx, const std::string& name, graph::TextureHandle illumination,
                             graph::TextureHandle reprojection, graph::BufferHandle tiles, const Histories& histories,
                             const SvgfTemporal& classified, const SvgfTemporalSettings& settings) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("svgf/temporal_fallback");
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    const auto historyValid = params.slot("historyValid", rhi::ScalarType::Uint32);
    return ctx.graph.addPass<SvgfTemporal>(name + ".fallback", [&](graph::PassBuilder& b, SvgfTemporal& o) {
        b.sample("illumination", illumination);
        b.sample("reprojection", reprojection);
        b.sample("color_history", histories.color);
        b.sample("moments_history", histories.moments);
        const auto list = b.readIndirect("tiles", tiles);
        o.color = b.readWrite("color", classified.color);
        o.moments = b.readWrite("moments", classified.moments);
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            params.set(historyValid, pc.historyValid() ? 1u : 0u);
            pc.dispatchIndirect(pipeline, group, list, params);
        };
    });
}

} // namespace

SvgfTemporal addSvgfTemporalPass(NodeContext& ctx, const std::string& name, graph::TextureHandle illumination,
                                 graph::TextureHandle reprojection, graph::TextureHandle colorHistory,
                                 const SvgfTemporalSettings& settings) {
    const graph::BufferHandle tiles = reprojectionFallbackTiles(ctx.graph, reprojection);
    const rhi::ComputePipeline pipeline =
        ctx.pipelines.get("svgf/temporal_accumulation", {{"fallbackInListedTiles", tiles.valid() ? 1.0 : 0.0}});
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    const auto historyValid = params.slot("historyValid", rhi::ScalarType::Uint32);
    Histories histories;
    const auto classified = ctx.graph.addPass<SvgfTemporal>(name, [&](graph::PassBuilder& b, SvgfTemporal& o) {
        b.sample("illumination", illumination);
        b.sample("reprojection", reprojection);
        const auto color = b.create(name, fullSize());
        const auto moments = b.create(name + ".moments", fullSize());
        // Without a colour history of the caller's, this pass accumulates its own output.
        histories = {colorHistory.valid() ? colorHistory : ctx.graph.history(color), ctx.graph.history(moments)};
        b.sample("color_history", histories.color);
        b.sample("moments_history", histories.moments);
        o.color = b.write("color", color);
        o.moments = b.write("moments", moments);
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            params.set(historyValid, pc.historyValid() ? 1u : 0u);
            pc.dispatch(pipeline, group, pc.texture(o.color).size(), params);
        };
    });
    if (!tiles.valid()) return classified;
    return addFallbackPass(ctx, name, illumination, reprojection, tiles, histories, classified, settings);
}

} // namespace hush::passes
