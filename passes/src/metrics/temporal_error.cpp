#include <hush/passes/metrics/temporal_error.hpp>

#include <cmath>

#include <hush/passes/metrics/partial_sums.hpp>
#include <hush/core/error.hpp>

namespace hush::passes {

graph::BufferHandle addTemporalErrorPass(NodeContext& ctx, const std::string& name, graph::TextureHandle current,
                                         graph::TextureHandle previous) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("metrics/temporal_error");
    struct Out {
        graph::BufferHandle partials;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        const graph::InputSpec fullSizeInput{.size = graph::SizeSpec::relative()};
        b.sample("current", current, fullSizeInput);
        b.sample("previous", previous, fullSizeInput);
        o.partials = b.write("partials", b.create(name + ".partials", metricsPartialsInfo()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, {kMetricsGridThreads, kMetricsGridThreads}); };
    });
    ctx.graph.markOutput(out.partials);
    return out.partials;
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
