#include <hush/passes/metrics/error_metrics.hpp>

#include <cmath>
#include <limits>

#include <hush/passes/metrics/partial_sums.hpp>
#include <hush/core/error.hpp>

namespace hush::passes {

namespace {
struct ErrorParams {
    float epsilon;
};
} // namespace

graph::BufferHandle addErrorMetricsPass(NodeContext& ctx, const std::string& name, graph::TextureHandle image,
                                        graph::TextureHandle reference, const MetricsSettings& settings) {
    validateMetricsSettings(settings);
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("metrics/error");
    const ErrorParams params{settings.relMseEpsilon};
    graph::BufferHandle out;
    ctx.graph.addPass(name, [&](graph::PassBuilder& b) {
        const graph::InputSpec fullSizeInput{.size = graph::SizeSpec::relative()};
        auto a = b.sample("image", image, fullSizeInput);
        auto r = b.sample("reference", reference, fullSizeInput);
        out = b.write("partials", b.create(name + ".partials", metricsPartialsInfo()));
        auto group = b.bindGroup(pipeline, 0,
                                 {{.name = "image", .texture = a},
                                  {.name = "reference", .texture = r},
                                  {.name = "Partials", .buffer = out}});
        return [=](graph::PassContext& pc) {
            pc.dispatch(pipeline, group, {kMetricsGridThreads, kMetricsGridThreads}, params);
        };
    });
    ctx.graph.markOutput(out);
    return out;
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
