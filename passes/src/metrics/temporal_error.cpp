#include <hush/passes/metrics/temporal_error.hpp>

#include <cmath>

#include <hush/passes/metrics/partial_sums.hpp>
#include <hush/core/error.hpp>

namespace hush::passes {

graph::BufferHandle addTemporalErrorPass(NodeContext& ctx, const std::string& name, graph::TextureHandle current,
                                         graph::TextureHandle previous) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("metrics/temporal_error");
    graph::BufferHandle out;
    ctx.graph.addPass(name, [&](graph::PassBuilder& b) {
        const graph::InputSpec fullSizeInput{.size = graph::SizeSpec::relative()};
        auto c = b.sample("current", current, fullSizeInput);
        auto p = b.sample("previous", previous, fullSizeInput);
        out = b.write("partials", b.create(name + ".partials", metricsPartialsInfo()));
        auto group = b.bindGroup(pipeline, 0,
                                 {{.name = "current", .texture = c},
                                  {.name = "previous", .texture = p},
                                  {.name = "Partials", .buffer = out}});
        return [=](graph::PassContext& pc) {
            pc.dispatch(pipeline, group, {kMetricsGridThreads, kMetricsGridThreads});
        };
    });
    ctx.graph.markOutput(out);
    return out;
}

TemporalError temporalErrorFromPartials(std::span<const float> partials) {
    const auto [sum, finite, nonFinite, unused] = sumPartials(partials);
    (void)unused;
    if (!std::isfinite(sum))
        throw Error(ErrorKind::InvalidArgument,
                    "temporal error: the luminance sum overflowed fp32; clamp or rescale the frames first");
    TemporalError t;
    t.pixels = uint64_t(std::llround(finite));
    t.nonFinitePixels = uint64_t(std::llround(nonFinite));
    if (t.pixels == 0)
        throw Error(ErrorKind::InvalidArgument, "temporal error: none of the " + std::to_string(t.nonFinitePixels) +
                                                    " pixels is finite in both frames (NaN or Inf in RGB)");
    t.error = sum / double(t.pixels);
    return t;
}

} // namespace hush::passes
