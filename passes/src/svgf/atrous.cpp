#include <hush/passes/svgf/atrous.hpp>

#include <hush/passes/common/atrous_lattice.hpp>
#include <hush/passes/common/normal_power.hpp>
#include <hush/passes/settings_push_constants.hpp>
#include <hush/passes/svgf/variance_prefilter.hpp>

namespace hush::passes {

namespace {
constexpr uint32_t kAtrousBlock = 4;   // pixels per invocation and axis: kBlock in shaders/svgf/atrous.comp
} // namespace

uint32_t svgfAtrousStep(uint32_t level) {
    constexpr uint32_t kMaxLevel = 16;
    return 1u << (level < kMaxLevel ? level : kMaxLevel);
}

graph::TextureHandle addSvgfAtrousPass(NodeContext& ctx, const std::string& name, graph::TextureHandle illumVariance,
                                       graph::TextureHandle prefilteredVariance, const Surface& surface,
                                       uint32_t level, const SvgfAtrousSettings& s) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("svgf/atrous", {normalPowerConstant("wholeSigmaN", s.sigmaN)});
    rhi::PushConstants params(pipeline);
    setFromSettings(params, s);
    params.set("step", int32_t(svgfAtrousStep(level)));
    struct Out {
        graph::TextureHandle filtered;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("illum_variance", illumVariance);
        b.sample("prefiltered_variance", prefilteredVariance);
        sampleSurface(b, surface);
        o.filtered = b.write("filtered", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) {
            const rhi::Extent2D size = pc.texture(o.filtered).size();
            pc.dispatch(pipeline, group, atrousThreads(size, svgfAtrousStep(level), kAtrousBlock), params);
        };
    });
    return out.filtered;
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
