#include <hush/passes/common/demodulate.hpp>

#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

graph::TextureHandle addDemodulatePass(NodeContext& ctx, const std::string& name, graph::TextureHandle radiance,
                                       graph::TextureHandle albedo, const DemodulateSettings& settings,
                                       graph::TextureHandle emission) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("common/demodulate");
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    params.set("hasEmission", emission.valid());
    struct Out {
        graph::TextureHandle illumination;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("radiance", radiance);
        b.sample("albedo", albedo);
        b.sample("emission", emission, {.optional = true});
        o.illumination = b.write("illumination", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(o.illumination).size(), params); };
    });
    return out.illumination;
}

} // namespace hush::passes
