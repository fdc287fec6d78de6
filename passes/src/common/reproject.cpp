#include <hush/passes/common/reproject.hpp>

#include <hush/passes/common/tile_list.hpp>
#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

namespace {
// The shaders' tile (common/reproject.glsl's kTile): one 8x8 workgroup.
constexpr rhi::Extent2D kReprojectTile{8, 8};

struct Reprojection {
    graph::TextureHandle decision;
    graph::BufferHandle tiles;
};

// "<name>.fallback": the whole decision, 3x3 fallback included, over the tiles that
// "<name>" listed (passes/common/tile_list.hpp).
graph::TextureHandle addFallbackPass(NodeContext& ctx, const std::string& name, graph::TextureHandle motion,
                                     const Surface& current, const Surface& previous, const Reprojection& classified,
                                     const ReprojectSettings& settings) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("common/reproject_fallback");
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    const auto historyValid = params.slot("historyValid", rhi::ScalarType::Uint32);
    struct Out {
        graph::TextureHandle reprojection;
    };
    const auto out = ctx.graph.addPass<Out>(name + ".fallback", [&](graph::PassBuilder& b, Out& o) {
        b.sample("motion", motion);
        sampleSurface(b, current);
        sampleSurface(b, previous, "previous_");
        const auto tiles = b.readIndirect("tiles", classified.tiles);
        o.reprojection = b.readWrite("reprojection", classified.decision);
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            params.set(historyValid, pc.historyValid() ? 1u : 0u);
            pc.dispatchIndirect(pipeline, group, tiles, params);
        };
    });
    return out.reprojection;
}
} // namespace

graph::TextureHandle addReprojectPass(NodeContext& ctx, const std::string& name, graph::TextureHandle motion,
                                      const Surface& current, const Surface& previous,
                                      const ReprojectSettings& settings) {
    const graph::BufferHandle tiles = addTileListPass(ctx, name + ".tiles", kReprojectTile);
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("common/reproject");
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    const auto historyValid = params.slot("historyValid", rhi::ScalarType::Uint32);
    const auto classified = ctx.graph.addPass<Reprojection>(name, [&](graph::PassBuilder& b, Reprojection& o) {
        b.sample("motion", motion);
        sampleSurface(b, current);
        sampleSurface(b, previous, "previous_");
        o.tiles = b.readWrite("tiles", tiles);
        o.decision = b.write("reprojection", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            params.set(historyValid, pc.historyValid() ? 1u : 0u);
            pc.dispatch(pipeline, group, pc.texture(o.decision).size(), params);
        };
    });
    return addFallbackPass(ctx, name, motion, current, previous, classified, settings);
}

graph::TextureHandle addReprojectPass(NodeContext& ctx, const std::string& name, graph::TextureHandle motion,
                                      const Surface& current, const ReprojectSettings& settings) {
    return addReprojectPass(ctx, name, motion, current, surfaceHistory(ctx, current), settings);
}

graph::BufferHandle reprojectionFallbackTiles(const graph::RenderGraph& graph, graph::TextureHandle decision) {
    const auto& resources = graph.model().resources;
    if (decision.index >= resources.size()) return {};
    return graph.findBuffer(resources[decision.index].name + ".tiles");
}

} // namespace hush::passes
