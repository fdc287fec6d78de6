#include <hush/passes/svgf/temporal_accumulation.hpp>

namespace hush::passes {

namespace {
// Push constants of shaders/svgf/temporal_accumulation.comp (same order).
struct TemporalParams {
    float alpha;
    float momentsAlpha;
    float maxHistoryLength;
    uint32_t historyValid;
};
} // namespace

SvgfTemporal addSvgfTemporalPass(NodeContext& ctx, const std::string& name, graph::TextureHandle illumination,
                                 graph::TextureHandle reprojection, const std::string& colorHistoryName,
                                 const SvgfTemporalSettings& settings) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("svgf/temporal_accumulation");
    const std::string momentsName = name + ".moments";
    const graph::TextureHandle colorHistory = ctx.graph.history(colorHistoryName, fullSize());
    const graph::TextureHandle momentsHistory = ctx.graph.history(momentsName, fullSize());
    SvgfTemporal result;
    ctx.graph.addPass(name, [&](graph::PassBuilder& b) {
        auto in = b.sample("illumination", illumination);
        auto decision = b.sample("reprojection", reprojection);
        auto prevColor = b.sample("color_history", colorHistory);
        auto prevMoments = b.sample("moments_history", momentsHistory);
        auto color = b.write("color", b.create(name, fullSize()));
        auto moments = b.write("moments", b.create(momentsName, fullSize()));
        auto group = b.bindGroup(pipeline, 0,
                                 {{.name = "illumination", .texture = in},
                                  {.name = "reprojection", .texture = decision},
                                  {.name = "colorHistory", .texture = prevColor},
                                  {.name = "momentsHistory", .texture = prevMoments},
                                  {.name = "color", .texture = color},
                                  {.name = "moments", .texture = moments}});
        result = {color, moments};
        const SvgfTemporalSettings s = settings;
        return [=](graph::PassContext& pc) {
            const TemporalParams params{s.alpha, s.momentsAlpha, s.maxHistoryLength, pc.historyValid() ? 1u : 0u};
            pc.dispatch(pipeline, group, pc.texture(color).size(), params);
        };
    });
    return result;
}

} // namespace hush::passes
