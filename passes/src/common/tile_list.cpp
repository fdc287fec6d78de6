#include <hush/passes/common/tile_list.hpp>

namespace hush::passes {

uint64_t tileListWords(rhi::Extent2D size, rhi::Extent2D tile) {
    const uint64_t across = (uint64_t(size.width) + tile.width - 1) / tile.width;
    const uint64_t down = (uint64_t(size.height) + tile.height - 1) / tile.height;
    return 4 + 2 * across * down;
}

graph::BufferHandle addTileListPass(NodeContext& ctx, const std::string& name, rhi::Extent2D tile) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("common/clear_tile_list");
    struct Out {
        graph::BufferHandle tiles;
    };
    const graph::BufferInfo info{.sizeFromOutput = [tile](rhi::Extent2D output) {
        return 4 * tileListWords(output, tile);
    }};
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        o.tiles = b.write("tiles", b.create(name, info));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) {
            pc.dispatch(pipeline, group, {uint32_t(pc.buffer(o.tiles).size() / 4), 1});
        };
    });
    return out.tiles;
}

} // namespace hush::passes
