#include <hush/passes/mara/median.hpp>

namespace hush::passes {

graph::TextureHandle addMaraMedianPass(NodeContext& ctx, const std::string& name, graph::TextureHandle color) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("mara/median");
    struct Out {
        graph::TextureHandle median;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("color", color);
        o.median = b.write("median", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(o.median).size()); };
    });
    return out.median;
}

} // namespace hush::passes
