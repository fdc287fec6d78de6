#include <hush/passes/rdae/output.hpp>

#include <hush/core/error.hpp>

namespace hush::passes {

graph::TextureHandle addRdaeOutputPass(NodeContext& ctx, const std::string& name, const RdaeTensor& features) {
    if (features.channels != 3 || features.level != 0)
        throw Error(ErrorKind::InvalidArgument, "rdae output '" + name + "' takes 3 channels at level 0, got " +
                                                    std::to_string(features.channels) + " at level " +
                                                    std::to_string(features.level));
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("rdae/output");
    struct Out {
        graph::TextureHandle illumination;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("features", features.texture);
        o.illumination = b.write("illumination", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(o.illumination).size()); };
    });
    return out.illumination;
}

} // namespace hush::passes
