#include <hush/passes/common/surface.hpp>

namespace hush::passes {

Surface addSurfacePass(NodeContext& ctx, const std::string& name, graph::TextureHandle normal,
                       graph::TextureHandle depth, graph::TextureHandle meshId) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("common/surface");
    Surface out;
    ctx.graph.addPass(name, [&](graph::PassBuilder& b) {
        auto n = b.sample("normal", normal);
        auto z = b.sample("depth", depth);
        auto id = b.sample("meshid", meshId);
        auto nd = b.write("normal_depth", b.create(name + ".normal_depth", fullSize()));
        auto gm = b.write("gradient_mesh", b.create(name + ".gradient_mesh", fullSize()));
        auto group = b.bindGroup(pipeline, 0,
                                 {{.name = "normal", .texture = n},
                                  {.name = "depth", .texture = z},
                                  {.name = "meshId", .texture = id},
                                  {.name = "normalDepth", .texture = nd},
                                  {.name = "gradientMesh", .texture = gm}});
        out = {nd, gm};
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(nd).size()); };
    });
    return out;
}

Surface surfaceHistory(NodeContext& ctx, const std::string& name) {
    return {ctx.graph.history(name + ".normal_depth", fullSize()),
            ctx.graph.history(name + ".gradient_mesh", fullSize())};
}

} // namespace hush::passes
