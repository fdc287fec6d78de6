#include <hush/passes/svgf/variance_prefilter.hpp>

namespace hush::passes {

graph::TextureHandle addSvgfVariancePrefilterPass(NodeContext& ctx, const std::string& name,
                                                  graph::TextureHandle illumVariance) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("svgf/variance_prefilter");
    graph::TextureHandle result;
    ctx.graph.addPass(name, [&](graph::PassBuilder& b) {
        auto in = b.sample("illum_variance", illumVariance);
        auto out = b.write("variance", b.create(name, fullSize(rhi::Format::R32Float)));
        auto group = b.bindGroup(pipeline, 0,
                                 {{.name = "illumVariance", .texture = in}, {.name = "variance", .texture = out}});
        result = out;
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(out).size()); };
    });
    return result;
}

} // namespace hush::passes
