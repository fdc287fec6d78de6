#include <hush/passes/bmfr/accumulate.hpp>

#include <cmath>

#include <hush/core/error.hpp>
#include <hush/passes/common/reproject.hpp>
#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

uint32_t bmfrAccumulateCountCap(const BmfrAccumulateSettings& settings) {
    const float w = settings.minWeight;
    if (!(std::isfinite(w) && w > 0.0f && w <= 1.0f))
        throw Error(ErrorKind::InvalidArgument,
                    "bmfr accumulate: minWeight must be in (0, 1], got " + std::to_string(w));
    if (settings.format != rhi::Format::RGBA32Float && settings.format != rhi::Format::RGBA16Float)
        throw Error(ErrorKind::InvalidArgument, "bmfr accumulate: format must be RGBA32Float or RGBA16Float");
    // In double, and with a little slack, so that 0.2f (0.200000003) gives 5, not 6.
    return uint32_t(std::ceil(1.0 / double(w) - 1e-5));
}

namespace {

// "<name>.fallback": every pixel of the tiles where the reprojection ran its 3x3
// fallback, every footprint (shaders/common/footprint_tiles.glsl).
graph::TextureHandle addFallbackPass(NodeContext& ctx, const std::string& name, graph::TextureHandle current,
                                     graph::TextureHandle reprojection, graph::BufferHandle tiles,
                                     graph::TextureHandle history, graph::TextureHandle classified,
                                     const BmfrAccumulateSettings& settings, uint32_t cap) {
    const bool half = settings.format == rhi::Format::RGBA16Float;
    const rhi::ComputePipeline pipeline =
        ctx.pipelines.get(half ? "bmfr/accumulate_fallback_rgba16f" : "bmfr/accumulate_fallback");
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    params.set("countCap", float(cap));
    const auto historyValid = params.slot("historyValid", rhi::ScalarType::Uint32);
    struct Out {
        graph::TextureHandle accumulated;
    };
    return ctx.graph.addPass<Out>(name + ".fallback", [&](graph::PassBuilder& b, Out& o) {
        b.sample("current", current);
        b.sample("reprojection", reprojection);
        b.sample("history", history);
        const auto list = b.readIndirect("tiles", tiles);
        o.accumulated = b.readWrite("accumulated", classified);
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            params.set(historyValid, pc.historyValid() ? 1u : 0u);
            pc.dispatchIndirect(pipeline, group, list, params);
        };
    }).accumulated;
}

} // namespace

graph::TextureHandle addBmfrAccumulatePass(NodeContext& ctx, const std::string& name, graph::TextureHandle current,
                                           graph::TextureHandle reprojection, const BmfrAccumulateSettings& settings) {
    const uint32_t cap = bmfrAccumulateCountCap(settings);
    const bool half = settings.format == rhi::Format::RGBA16Float;
    const graph::BufferHandle tiles = reprojectionFallbackTiles(ctx.graph, reprojection);
    // One shader per output format: the image's format qualifier must be literal.
    const rhi::ComputePipeline pipeline = ctx.pipelines.get(
        half ? "bmfr/accumulate_rgba16f" : "bmfr/accumulate", {{"fallbackInListedTiles", tiles.valid() ? 1.0 : 0.0}});
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    params.set("countCap", float(cap));
    const auto historyValid = params.slot("historyValid", rhi::ScalarType::Uint32);
    struct Out {
        graph::TextureHandle accumulated, history;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("current", current);
        b.sample("reprojection", reprojection);
        const auto accumulated = b.create(name, fullSize(settings.format));
        // The node's own output last frame: colour in rgb, sample count in alpha.
        o.history = ctx.graph.history(accumulated);
        b.sample("history", o.history);
        o.accumulated = b.write("accumulated", accumulated);
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            params.set(historyValid, pc.historyValid() ? 1u : 0u);
            pc.dispatch(pipeline, group, pc.texture(o.accumulated).size(), params);
        };
    });
    if (!tiles.valid()) return out.accumulated;
    return addFallbackPass(ctx, name, current, reprojection, tiles, out.history, out.accumulated, settings, cap);
}

} // namespace hush::passes
