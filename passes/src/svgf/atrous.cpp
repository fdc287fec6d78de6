#include <hush/passes/svgf/atrous.hpp>

#include <hush/passes/svgf/variance_prefilter.hpp>

namespace hush::passes {

namespace {
// Matches the push-constant block of shaders/svgf/atrous.comp.
struct AtrousParams {
    int32_t step;
    float sigmaZ, sigmaN, sigmaL;
    float depthEpsilon, luminanceEpsilon;
};
} // namespace

uint32_t svgfAtrousStep(uint32_t level) {
    constexpr uint32_t kMaxLevel = 16;
    return 1u << (level < kMaxLevel ? level : kMaxLevel);
}

graph::TextureHandle addSvgfAtrousPass(NodeContext& ctx, const std::string& name, graph::TextureHandle illumVariance,
                                       graph::TextureHandle prefilteredVariance, const Surface& surface,
                                       uint32_t level, const SvgfAtrousSettings& s) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("svgf/atrous");
    graph::TextureHandle result;
    ctx.graph.addPass(name, [&](graph::PassBuilder& b) {
        auto in = b.sample("illum_variance", illumVariance);
        auto var = b.sample("prefiltered_variance", prefilteredVariance);
        auto nd = b.sample("normal_depth", surface.normalDepth);
        auto gm = b.sample("gradient_mesh", surface.gradientMesh);
        auto out = b.write("filtered", b.create(name, fullSize()));
        auto group = b.bindGroup(pipeline, 0,
                                 {{.name = "illumVariance", .texture = in},
                                  {.name = "prefilteredVariance", .texture = var},
                                  {.name = "normalDepth", .texture = nd},
                                  {.name = "gradientMesh", .texture = gm},
                                  {.name = "filtered", .texture = out}});
        result = out;
        const AtrousParams params{int32_t(svgfAtrousStep(level)), s.sigmaZ, s.sigmaN, s.sigmaL,
                                  s.depthEpsilon, s.luminanceEpsilon};
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(out).size(), params); };
    });
    return result;
}

SvgfAtrousResult addSvgfAtrousLevels(NodeContext& ctx, const std::string& name, graph::TextureHandle illumVariance,
                                     const Surface& surface, const SvgfAtrousSettings& s) {
    SvgfAtrousResult result{illumVariance, illumVariance};
    graph::TextureHandle current = illumVariance;
    for (uint32_t i = 0; i < s.iterations; ++i) {
        const std::string index = std::to_string(i);
        // Eq. 5 reads the prefiltered variance of this level's own input: the
        // variance shrinks level by level, so w_l tightens as the filter widens.
        auto prefiltered = addSvgfVariancePrefilterPass(ctx, name + ".prefilter." + index, current);
        current = addSvgfAtrousPass(ctx, name + ".level." + index, current, prefiltered, surface, i, s);
        if (i == 0) result.firstLevel = current;
    }
    result.filtered = current;
    return result;
}

} // namespace hush::passes
