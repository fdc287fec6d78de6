#include <hush/passes/mara/compose.hpp>

#include <hush/core/error.hpp>

namespace hush::passes {

graph::TextureHandle addMaraComposePass(NodeContext& ctx, const std::string& name, const MaraComposeInputs& in,
                                        FrameCameraRef camera) {
    if (!camera)
        throw Error(ErrorKind::InvalidArgument, "node '" + name + "' needs the frame's camera (DenoiseInputs::camera)");
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("mara/compose");
    rhi::PushConstants params(pipeline);
    params.set("hasGlossy", in.glossy.valid());
    const auto cameraPosition = params.slot("cameraPosition", rhi::ScalarType::Float32, 4);
    struct Out {
        graph::TextureHandle radiance;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("direct", in.direct);
        b.sample("matte", in.matte);
        b.sample("glossy", in.glossy, {.optional = true});
        b.sample("albedo", in.albedo);
        b.sample("specular", in.specular);
        b.sample("normal_depth", in.surface.normalDepth);
        b.sample("position", in.position);
        o.radiance = b.write("radiance", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            const auto& p = camera->position;
            const float position[4] = {p[0], p[1], p[2], 1.0f};
            params.set(cameraPosition, position);
            pc.dispatch(pipeline, group, pc.texture(o.radiance).size(), params);
        };
    });
    return out.radiance;
}

} // namespace hush::passes
