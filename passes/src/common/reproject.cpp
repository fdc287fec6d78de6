#include <hush/passes/common/reproject.hpp>

#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

graph::TextureHandle addReprojectPass(NodeContext& ctx, const std::string& name, graph::TextureHandle motion,
                                      const Surface& current, const Surface& previous,
                                      const ReprojectSettings& settings) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("common/reproject");
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    const auto historyValid = params.slot("historyValid", rhi::ScalarType::Uint32);
    struct Out {
        graph::TextureHandle reprojection;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("motion", motion);
        sampleSurface(b, current);
        sampleSurface(b, previous, "previous_");
        o.reprojection = b.write("reprojection", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            params.set(historyValid, pc.historyValid() ? 1u : 0u);
            pc.dispatch(pipeline, group, pc.texture(o.reprojection).size(), params);
        };
    });
    return out.reprojection;
}

graph::TextureHandle addReprojectPass(NodeContext& ctx, const std::string& name, graph::TextureHandle motion,
                                      const Surface& current, const ReprojectSettings& settings) {
    return addReprojectPass(ctx, name, motion, current, surfaceHistory(ctx, current), settings);
}

} // namespace hush::passes
