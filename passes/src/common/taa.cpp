#include <hush/passes/common/taa.hpp>

#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

graph::TextureHandle addTaaPass(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                graph::TextureHandle motion, const TaaSettings& settings,
                                graph::TextureHandle reprojection) {
    const rhi::ComputePipeline pipeline =
        ctx.pipelines.get("common/taa", {{"box", double(settings.box)},
                                         {"rectify", double(settings.rectify)},
                                         {"historyFilter", double(settings.historyFilter)},
                                         {"useReprojection", reprojection.valid() ? 1.0 : 0.0}});
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    const auto historyValid = params.slot("historyValid", rhi::ScalarType::Uint32);
    struct Out {
        graph::TextureHandle resolved;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("color", color);
        b.sample("motion", motion);
        b.sample("reprojection", reprojection, {.optional = true});
        const auto resolved = b.create(name, fullSize());
        // Last frame's output of this very pass is the TAA history.
        b.sample("history", ctx.graph.history(resolved));
        o.resolved = b.write("resolved", resolved);
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            params.set(historyValid, pc.historyValid() ? 1u : 0u);
            pc.dispatch(pipeline, group, pc.texture(o.resolved).size(), params);
        };
    });
    return out.resolved;
}

} // namespace hush::passes
