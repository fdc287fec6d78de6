#include <hush/passes/common/demodulate.hpp>

namespace hush::passes {

graph::TextureHandle addDemodulatePass(NodeContext& ctx, const std::string& name, graph::TextureHandle radiance,
                                       graph::TextureHandle albedo, const DemodulateSettings& settings,
                                       graph::TextureHandle emission) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("common/demodulate");
    graph::TextureHandle result;
    ctx.graph.addPass(name, [&](graph::PassBuilder& b) {
        auto in = b.sample("radiance", radiance);
        auto alb = b.sample("albedo", albedo);
        // Without emission the shader never reads that binding: give it the radiance.
        auto em = emission.valid() ? b.sample("emission", emission) : in;
        auto out = b.write("illumination", b.create(name, fullSize()));
        auto group = b.bindGroup(pipeline, 0,
                                 {{.name = "radiance", .texture = in},
                                  {.name = "albedo", .texture = alb},
                                  {.name = "illumination", .texture = out},
                                  {.name = "emission", .texture = em}});
        result = out;
        struct {
            float eps;
            uint32_t hasEmission;
        } params{settings.eps, emission.valid() ? 1u : 0u};
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(out).size(), params); };
    });
    return result;
}

graph::TextureHandle addRemodulatePass(NodeContext& ctx, const std::string& name, graph::TextureHandle a,
                                       graph::TextureHandle b, graph::TextureHandle albedo,
                                       const DemodulateSettings& settings, graph::TextureHandle emission) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("common/remodulate");
    graph::TextureHandle result;
    ctx.graph.addPass(name, [&](graph::PassBuilder& pb) {
        auto inA = pb.sample("a", a);
        auto inB = b.valid() ? pb.sample("b", b) : inA;
        auto alb = pb.sample("albedo", albedo);
        auto em = emission.valid() ? pb.sample("emission", emission) : inA;
        auto out = pb.write("radiance", pb.create(name, fullSize()));
        auto group = pb.bindGroup(pipeline, 0,
                                  {{.name = "illuminationA", .texture = inA},
                                   {.name = "illuminationB", .texture = inB},
                                   {.name = "albedo", .texture = alb},
                                   {.name = "radiance", .texture = out},
                                   {.name = "emission", .texture = em}});
        result = out;
        struct {
            float eps;
            uint32_t termCount;
            uint32_t hasEmission;
        } params{settings.eps, b.valid() ? 2u : 1u, emission.valid() ? 1u : 0u};
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(out).size(), params); };
    });
    return result;
}

} // namespace hush::passes
