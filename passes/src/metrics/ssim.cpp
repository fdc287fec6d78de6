#include <hush/passes/metrics/ssim.hpp>

#include <cmath>

#include <hush/passes/metrics/partial_sums.hpp>
#include <hush/core/error.hpp>

namespace hush::passes {

namespace {
struct SsimParams {
    float c1, c2, sigma;
};
} // namespace

SsimOutputs addSsimPass(NodeContext& ctx, const std::string& name, graph::TextureHandle image,
                        graph::TextureHandle reference, const MetricsSettings& settings) {
    validateMetricsSettings(settings);
    const rhi::ComputePipeline mapPipeline = ctx.pipelines.get("metrics/ssim_map");
    const rhi::ComputePipeline reducePipeline = ctx.pipelines.get("metrics/reduce_map");
    const SsimParams params{float(settings.ssimC1()), float(settings.ssimC2()), settings.ssimSigma};
    SsimOutputs out;
    ctx.graph.addPass(name + ".map", [&](graph::PassBuilder& b) {
        const graph::InputSpec fullSizeInput{.size = graph::SizeSpec::relative()};
        auto a = b.sample("image", image, fullSizeInput);
        auto r = b.sample("reference", reference, fullSizeInput);
        out.map = b.write("map", b.create(name + ".map", fullSize(rhi::Format::RGBA32Float)));
        auto group = b.bindGroup(mapPipeline, 0,
                                 {{.name = "image", .texture = a},
                                  {.name = "reference", .texture = r},
                                  {.name = "ssimMap", .texture = out.map}});
        const auto map = out.map;
        return [=](graph::PassContext& pc) { pc.dispatch(mapPipeline, group, pc.texture(map).size(), params); };
    });
    ctx.graph.addPass(name + ".reduce", [&](graph::PassBuilder& b) {
        auto map = b.sample("map", out.map);
        out.partials = b.write("partials", b.create(name + ".partials", metricsPartialsInfo()));
        auto group = b.bindGroup(reducePipeline, 0,
                                 {{.name = "map", .texture = map}, {.name = "Partials", .buffer = out.partials}});
        return [=](graph::PassContext& pc) {
            pc.dispatch(reducePipeline, group, {kMetricsGridThreads, kMetricsGridThreads});
        };
    });
    ctx.graph.markOutput(out.partials);
    return out;
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
