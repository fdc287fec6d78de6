#include <hush/passes/svgf/variance_prefilter.hpp>

namespace hush::passes {

namespace {
constexpr uint32_t kPrefilterBlock = 8;   // pixels per invocation per axis: kBlock in shaders/svgf/variance_prefilter.comp
} // namespace

graph::TextureHandle addSvgfVariancePrefilterPass(NodeContext& ctx, const std::string& name,
                                                  graph::TextureHandle illumVariance) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("svgf/variance_prefilter");
    struct Out {
        graph::TextureHandle prefilteredVariance;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("illum_variance", illumVariance);
        o.prefilteredVariance =
            b.write("prefiltered_variance", b.create(name, fullSize(rhi::Format::R32Float)));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) {
            const rhi::Extent2D size = pc.texture(o.prefilteredVariance).size();
            pc.dispatch(pipeline, group,
                        {(size.width + kPrefilterBlock - 1) / kPrefilterBlock, (size.height + kPrefilterBlock - 1) / kPrefilterBlock});
        };
    });
    return out.prefilteredVariance;
}

} // namespace hush::passes
