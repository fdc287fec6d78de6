#include <hush/passes/metrics/ssim.hpp>

#include <cmath>

#include <hush/passes/metrics/partial_sums.hpp>
#include <hush/core/error.hpp>

namespace hush::passes {

SsimOutputs addSsimPass(NodeContext& ctx, const std::string& name, graph::TextureHandle image,
                        graph::TextureHandle reference, const MetricsSettings& settings) {
    validateMetricsSettings(settings);
    const rhi::ComputePipeline mapPipeline = ctx.pipelines.get("metrics/ssim_map");
    const rhi::ComputePipeline reducePipeline = ctx.pipelines.get("metrics/reduce_map");
    rhi::PushConstants params(mapPipeline);
    params.set("c1", float(settings.ssimC1())).set("c2", float(settings.ssimC2())).set("sigma", settings.ssimSigma);
    struct Map {
        graph::TextureHandle map;
    };
    const auto map = ctx.graph.addPass<Map>(name + ".map", [&](graph::PassBuilder& b, Map& o) {
        const graph::InputSpec fullSizeInput{.size = graph::SizeSpec::relative()};
        b.sample("image", image, fullSizeInput);
        b.sample("reference", reference, fullSizeInput);
        o.map = b.write("map", b.create(name + ".map", fullSize(rhi::Format::RGBA32Float)));
        const auto group = b.bindGroup(mapPipeline);
        return [=](graph::PassContext& pc) { pc.dispatch(mapPipeline, group, pc.texture(o.map).size(), params); };
    });
    struct Reduce {
        graph::BufferHandle partials;
    };
    const auto reduced = ctx.graph.addPass<Reduce>(name + ".reduce", [&](graph::PassBuilder& b, Reduce& o) {
        b.sample("map", map.map);
        o.partials = b.write("partials", b.create(name + ".partials", metricsPartialsInfo()));
        const auto group = b.bindGroup(reducePipeline);
        return [=](graph::PassContext& pc) {
            pc.dispatch(reducePipeline, group, {kMetricsGridThreads, kMetricsGridThreads});
        };
    });
    ctx.graph.markOutput(reduced.partials);
    return {map.map, reduced.partials};
}

SsimResult ssimFromPartials(std::span<const float> partials) {
    const auto [sum, windows, excluded, unused] = sumPartials(partials);
    (void)unused;
    if (!std::isfinite(sum))
        throw Error(ErrorKind::InvalidArgument,
                    "ssim: the window statistics overflowed fp32 (values beyond about 1e18); "
                    "clamp or rescale the images first");
    SsimResult r;
    r.windows = uint64_t(std::llround(windows));
    r.excludedWindows = uint64_t(std::llround(excluded));
    if (r.windows == 0)
        throw Error(ErrorKind::InvalidArgument, "ssim: every one of the " + std::to_string(r.excludedWindows) +
                                                    " windows holds a non-finite value (NaN or Inf in RGB)");
    r.ssim = sum / double(r.windows);
    return r;
}

} // namespace hush::passes
