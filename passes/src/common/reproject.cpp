#include <hush/passes/common/reproject.hpp>

namespace hush::passes {

namespace {
// Push constants of shaders/common/reproject.comp (std430 layout, same order).
struct ReprojectParams {
    float normalCosine;
    float depthSlopeTolerance;
    float depthRelativeTolerance;
    uint32_t fallback3x3;
    uint32_t historyValid;
};
} // namespace

graph::TextureHandle addReprojectPass(NodeContext& ctx, const std::string& name, graph::TextureHandle motion,
                                      const Surface& current, const Surface& previous,
                                      const ReprojectSettings& settings) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("common/reproject");
    graph::TextureHandle result;
    ctx.graph.addPass(name, [&](graph::PassBuilder& b) {
        auto mv = b.sample("motion", motion);
        auto nd = b.sample("normal_depth", current.normalDepth);
        auto gm = b.sample("gradient_mesh", current.gradientMesh);
        auto prevNd = b.sample("previous_normal_depth", previous.normalDepth);
        auto prevGm = b.sample("previous_gradient_mesh", previous.gradientMesh);
        auto out = b.write("decision", b.create(name, fullSize()));
        auto group = b.bindGroup(pipeline, 0,
                                 {{.name = "motion", .texture = mv},
                                  {.name = "normalDepth", .texture = nd},
                                  {.name = "gradientMesh", .texture = gm},
                                  {.name = "previousNormalDepth", .texture = prevNd},
                                  {.name = "previousGradientMesh", .texture = prevGm},
                                  {.name = "decision", .texture = out}});
        result = out;
        const ReprojectSettings s = settings;
        return [=](graph::PassContext& pc) {
            const ReprojectParams params{s.normalCosine, s.depthSlopeTolerance, s.depthRelativeTolerance,
                                         s.fallback3x3 ? 1u : 0u, pc.historyValid() ? 1u : 0u};
            pc.dispatch(pipeline, group, pc.texture(out).size(), params);
        };
    });
    return result;
}

} // namespace hush::passes
