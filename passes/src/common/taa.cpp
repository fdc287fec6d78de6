#include <hush/passes/common/taa.hpp>

#include <hush/passes/common/tile_list.hpp>
#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

namespace {

// The TAA shader's tile (common/taa.glsl's kTile): one 8x8 workgroup.
constexpr rhi::Extent2D kTaaTile{8, 8};

rhi::ComputePipeline taaPipeline(NodeContext& ctx, const char* shader, const TaaSettings& settings, bool reprojection) {
    return ctx.pipelines.get(shader, {{"box", double(settings.box)},
                                      {"rectify", double(settings.rectify)},
                                      {"historyFilter", double(settings.historyFilter)},
                                      {"useReprojection", reprojection ? 1.0 : 0.0}});
}

struct TaaInputs {
    graph::TextureHandle color, motion, reprojection;
};

struct Resolved {
    graph::TextureHandle resolved, history;
    graph::BufferHandle tiles;
};

// "<name>.partial": every pixel of the tiles "<name>" listed, partial footprints
// included (passes/common/tile_list.hpp).
graph::TextureHandle addPartialPass(NodeContext& ctx, const std::string& name, const TaaInputs& in,
                                    const Resolved& classified, const TaaSettings& settings) {
    const rhi::ComputePipeline pipeline = taaPipeline(ctx, "common/taa_partial", settings, true);
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    const auto historyValid = params.slot("historyValid", rhi::ScalarType::Uint32);
    struct Out {
        graph::TextureHandle resolved;
    };
    return ctx.graph.addPass<Out>(name + ".partial", [&](graph::PassBuilder& b, Out& o) {
        b.sample("color", in.color);
        b.sample("motion", in.motion);
        b.sample("reprojection", in.reprojection);
        b.sample("history", classified.history);
        const auto tiles = b.readIndirect("tiles", classified.tiles);
        o.resolved = b.readWrite("resolved", classified.resolved);
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            params.set(historyValid, pc.historyValid() ? 1u : 0u);
            pc.dispatchIndirect(pipeline, group, tiles, params);
        };
    }).resolved;
}

} // namespace

graph::TextureHandle addTaaPass(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                graph::TextureHandle motion, const TaaSettings& settings,
                                graph::TextureHandle reprojection) {
    // With a decision, partial footprints go to listed tiles; without one, one pass.
    const bool split = reprojection.valid();
    const graph::BufferHandle tiles = split ? addTileListPass(ctx, name + ".tiles", kTaaTile) : graph::BufferHandle{};
    const rhi::ComputePipeline pipeline = taaPipeline(ctx, split ? "common/taa_classify" : "common/taa", settings, split);
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    const auto historyValid = params.slot("historyValid", rhi::ScalarType::Uint32);
    const auto out = ctx.graph.addPass<Resolved>(name, [&](graph::PassBuilder& b, Resolved& o) {
        b.sample("color", color);
        b.sample("motion", motion);
        b.sample("reprojection", reprojection, {.optional = true});
        const auto resolved = b.create(name, fullSize());
        // Last frame's output of this very pass is the TAA history.
        o.history = ctx.graph.history(resolved);
        b.sample("history", o.history);
        if (split) o.tiles = b.readWrite("tiles", tiles);
        o.resolved = b.write("resolved", resolved);
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            params.set(historyValid, pc.historyValid() ? 1u : 0u);
            pc.dispatch(pipeline, group, pc.texture(o.resolved).size(), params);
        };
    });
    if (!split) return out.resolved;
    return addPartialPass(ctx, name, {color, motion, reprojection}, out, settings);
}

} // namespace hush::passes
