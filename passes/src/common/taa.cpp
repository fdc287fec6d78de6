#include <hush/passes/common/taa.hpp>

namespace hush::passes {

graph::TextureHandle addTaaPass(NodeContext& ctx, const std::string& name, graph::TextureHandle current,
                                graph::TextureHandle motion, const TaaSettings& settings,
                                graph::TextureHandle reprojection) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("common/taa");
    // Last frame's value of the transient this pass creates under the same name.
    const graph::TextureHandle last = ctx.graph.history(name, fullSize());
    graph::TextureHandle result;
    ctx.graph.addPass(name, [&](graph::PassBuilder& b) {
        auto cur = b.sample("current", current);
        auto mv = b.sample("motion", motion);
        auto hist = b.sample("history", last);
        // Without a decision the shader never reads that binding: give it the motion.
        auto decision = reprojection.valid() ? b.sample("reprojection", reprojection) : mv;
        auto out = b.write("resolved", b.create(name, fullSize()));
        auto group = b.bindGroup(pipeline, 0,
                                 {{.name = "current", .texture = cur},
                                  {.name = "motion", .texture = mv},
                                  {.name = "history", .texture = hist},
                                  {.name = "resolved", .texture = out},
                                  {.name = "reprojection", .texture = decision}});
        result = out;
        struct Params {
            float alpha;
            float varianceGamma;
            uint32_t box;
            uint32_t rectify;
            uint32_t historyFilter;
            uint32_t useReprojection;
            uint32_t historyValid;
        };
        const Params base{settings.alpha,
                          settings.varianceGamma,
                          uint32_t(settings.box),
                          uint32_t(settings.rectify),
                          uint32_t(settings.historyFilter),
                          reprojection.valid() ? 1u : 0u,
                          0u};
        return [=](graph::PassContext& pc) {
            Params params = base;
            params.historyValid = pc.historyValid() ? 1u : 0u;
            pc.dispatch(pipeline, group, pc.texture(out).size(), params);
        };
    });
    return result;
}

} // namespace hush::passes
