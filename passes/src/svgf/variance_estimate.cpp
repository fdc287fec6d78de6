#include <hush/passes/svgf/variance_estimate.hpp>

#include <algorithm>

namespace hush::passes {

namespace {
// Push constants of shaders/svgf/variance_estimate.comp (same order).
struct VarianceParams {
    float minHistoryLength;
    int32_t radius;
    float sigmaZ;
    float sigmaN;
    float depthEpsilon;
    uint32_t shortHistoryBoost;
};
} // namespace

graph::TextureHandle addSvgfVariancePass(NodeContext& ctx, const std::string& name, const SvgfTemporal& temporal,
                                         const Surface& surface, const SvgfVarianceSettings& settings) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("svgf/variance_estimate");
    graph::TextureHandle result;
    ctx.graph.addPass(name, [&](graph::PassBuilder& b) {
        auto color = b.sample("color", temporal.color);
        auto moments = b.sample("moments", temporal.moments);
        auto nd = b.sample("normal_depth", surface.normalDepth);
        auto gm = b.sample("gradient_mesh", surface.gradientMesh);
        auto out = b.write("variance", b.create(name, fullSize()));
        auto group = b.bindGroup(pipeline, 0,
                                 {{.name = "color", .texture = color},
                                  {.name = "moments", .texture = moments},
                                  {.name = "normalDepth", .texture = nd},
                                  {.name = "gradientMesh", .texture = gm},
                                  {.name = "colorVariance", .texture = out}});
        result = out;
        const VarianceParams params{settings.minHistoryLength,
                                    std::clamp(settings.radius, 0, 16),
                                    settings.sigmaZ,
                                    settings.sigmaN,
                                    settings.depthEpsilon,
                                    settings.shortHistoryBoost ? 1u : 0u};
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(out).size(), params); };
    });
    return result;
}

} // namespace hush::passes
