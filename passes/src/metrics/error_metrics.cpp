#include <hush/passes/metrics/error_metrics.hpp>

#include <cmath>
#include <limits>

#include <hush/passes/metrics/partial_sums.hpp>
#include <hush/core/error.hpp>

namespace hush::passes {

graph::BufferHandle addErrorMetricsPass(NodeContext& ctx, const std::string& name, graph::TextureHandle image,
                                        graph::TextureHandle reference, const MetricsSettings& settings) {
    validateMetricsSettings(settings);
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("metrics/error");
    rhi::PushConstants params(pipeline);
    params.set("epsilon", settings.relMseEpsilon);
    struct Out {
        graph::BufferHandle partials;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        const graph::InputSpec fullSizeInput{.size = graph::SizeSpec::relative()};
        b.sample("image", image, fullSizeInput);
        b.sample("reference", reference, fullSizeInput);
        o.partials = b.write("partials", b.create(name + ".partials", metricsPartialsInfo()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) {
            pc.dispatch(pipeline, group, {kMetricsGridThreads, kMetricsGridThreads}, params);
        };
    });
    ctx.graph.markOutput(out.partials);
    return out.partials;
}

ErrorMetrics errorMetricsFromPartials(std::span<const float> partials, const MetricsSettings& settings) {
    validateMetricsSettings(settings);
    const auto [squared, relative, finite, nonFinite] = sumPartials(partials);
    if (!std::isfinite(squared) || !std::isfinite(relative))
        throw Error(ErrorKind::InvalidArgument,
                    "error metrics: the squared errors overflowed fp32 (differences beyond about 1e18); "
                    "clamp or rescale the images first");
    ErrorMetrics m;
    m.pixels = uint64_t(std::llround(finite));
    m.nonFinitePixels = uint64_t(std::llround(nonFinite));
    if (m.pixels == 0)
        throw Error(ErrorKind::InvalidArgument, "error metrics: none of the " + std::to_string(m.nonFinitePixels) +
                                                    " pixels is finite in both images (NaN or Inf in RGB)");
    const double values = 3.0 * double(m.pixels);   // RGB per pixel
    m.mse = squared / values;
    m.rmse = std::sqrt(m.mse);
    m.relMse = relative / values;
    // PSNR (dB) = 10 log10(peak^2 / MSE): identical images have no noise, PSNR = +inf.
    m.psnr = m.mse > 0.0 ? 10.0 * std::log10(settings.psnrPeak * settings.psnrPeak / m.mse)
                         : std::numeric_limits<double>::infinity();
    return m;
}

} // namespace hush::passes
