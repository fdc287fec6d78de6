#include <hush/passes/common/remodulate.hpp>

#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

graph::TextureHandle addRemodulatePass(NodeContext& ctx, const std::string& name, graph::TextureHandle a,
                                       graph::TextureHandle b, graph::TextureHandle albedo,
                                       const DemodulateSettings& settings, graph::TextureHandle emission) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("common/remodulate");
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    params.set("termCount", b.valid() ? 2u : 1u).set("hasEmission", emission.valid());
    struct Out {
        graph::TextureHandle radiance;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& pb, Out& o) {
        pb.sample("a", a);
        pb.sample("b", b, {.optional = true});
        pb.sample("albedo", albedo);
        pb.sample("emission", emission, {.optional = true});
        o.radiance = pb.write("radiance", pb.create(name, fullSize()));
        const auto group = pb.bindGroup(pipeline);
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(o.radiance).size(), params); };
    });
    return out.radiance;
}

} // namespace hush::passes
