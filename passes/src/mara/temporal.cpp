#include <hush/passes/mara/temporal.hpp>

#include <hush/core/error.hpp>
#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

namespace {
void requireCamera(const FrameCameraRef& camera, const std::string& name) {
    if (!camera)
        throw Error(ErrorKind::InvalidArgument, "node '" + name + "' needs the frame's camera (DenoiseInputs::camera)");
}
} // namespace

graph::TextureHandle addMaraMatteTemporalPass(NodeContext& ctx, const std::string& name, graph::TextureHandle matte,
                                              graph::TextureHandle motion, graph::TextureHandle position,
                                              graph::TextureHandle history, graph::TextureHandle positionHistory,
                                              FrameCameraRef camera, const MaraTemporalSettings& settings) {
    requireCamera(camera, name);
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("mara/matte_temporal");
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    const auto metresPerUnit = params.slot("metresPerUnit", rhi::ScalarType::Float32);
    const auto historyValid = params.slot("historyValid", rhi::ScalarType::Uint32);
    struct Out {
        graph::TextureHandle temporal;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("current", matte);
        b.sample("motion", motion);
        b.sample("position", position);
        b.sample("history", history);
        b.sample("position_history", positionHistory);
        o.temporal = b.write("temporal", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            params.set(metresPerUnit, camera->metresPerUnit);
            params.set(historyValid, pc.historyValid() ? 1u : 0u);
            pc.dispatch(pipeline, group, pc.texture(o.temporal).size(), params);
        };
    });
    return out.temporal;
}

graph::TextureHandle addMaraGlossyTemporalPass(NodeContext& ctx, const std::string& name, graph::TextureHandle glossy,
                                               graph::TextureHandle virtualpos, graph::TextureHandle virtualposHistory,
                                               FrameCameraRef camera, const MaraTemporalSettings& settings) {
    requireCamera(camera, name);
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("mara/glossy_temporal");
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    const auto viewProjection = params.slot("previousViewProjection", rhi::ScalarType::Float32, 16);
    const auto metresPerUnit = params.slot("metresPerUnit", rhi::ScalarType::Float32);
    const auto historyValid = params.slot("historyValid", rhi::ScalarType::Uint32);
    struct Out {
        graph::TextureHandle temporal;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("current", glossy);
        b.sample("virtualpos", virtualpos);
        b.sample("position_history", virtualposHistory);
        const auto temporal = b.create(name, fullSize());
        b.sample("history", ctx.graph.history(temporal));   // its own output, last frame
        o.temporal = b.write("temporal", temporal);
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            params.set(viewProjection, multiply(camera->previousProjection, camera->previousView));
            params.set(metresPerUnit, camera->metresPerUnit);
            params.set(historyValid, pc.historyValid() ? 1u : 0u);
            pc.dispatch(pipeline, group, pc.texture(o.temporal).size(), params);
        };
    });
    return out.temporal;
}

} // namespace hush::passes
