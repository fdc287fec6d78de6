#include <hush/passes/common/surface.hpp>

namespace hush::passes {

Surface addSurfacePass(NodeContext& ctx, const std::string& name, graph::TextureHandle normal,
                       graph::TextureHandle depth, graph::TextureHandle meshId) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("common/surface");
    return ctx.graph.addPass<Surface>(name, [&](graph::PassBuilder& b, Surface& o) {
        b.sample("normal", normal);
        b.sample("depth", depth);
        b.sample("meshid", meshId);
        o.normalDepth = b.write("normal_depth", b.create(name + ".normal_depth", fullSize()));
        o.gradientMesh = b.write("gradient_mesh", b.create(name + ".gradient_mesh", fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(o.normalDepth).size()); };
    });
}

Surface surfaceHistory(NodeContext& ctx, const Surface& current) {
    return {ctx.graph.history(current.normalDepth), ctx.graph.history(current.gradientMesh)};
}

void sampleSurface(graph::PassBuilder& b, const Surface& surface, std::string_view prefix) {
    b.sample(std::string(prefix) + "normal_depth", surface.normalDepth);
    b.sample(std::string(prefix) + "gradient_mesh", surface.gradientMesh);
}

} // namespace hush::passes
