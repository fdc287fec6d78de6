#pragma once
// MetricsEvaluator: the metrics for tools (benchmarks, quality tests, the CLI) that
// hold images on the CPU. It owns two textures and two small graphs on `device`:
// one computes RMSE, relative MSE, PSNR and SSIM, the other the temporal error.
// Each call uploads the images (Queue::writeTexture), runs its graph and waits.
#include <cstdint>
#include <span>

#include <hush/graph/render_graph.hpp>
#include <hush/passes/metrics/error_metrics.hpp>
#include <hush/passes/metrics/metrics_settings.hpp>
#include <hush/passes/metrics/ssim.hpp>
#include <hush/passes/metrics/temporal_error.hpp>
#include <hush/passes/pipeline_cache.hpp>

namespace hush::passes {

struct ImageMetrics {
    double rmse = 0, relMse = 0, psnr = 0, ssim = 0;
    uint64_t nonFinitePixels = 0;       // left out of RMSE, relMSE and PSNR
    uint64_t excludedSsimWindows = 0;   // left out of SSIM
};

class MetricsEvaluator {
public:
    // Throws hush::Error (InvalidArgument) on an empty size or invalid settings.
    MetricsEvaluator(rhi::Device device, rhi::Extent2D size, const MetricsSettings& settings = {});

    // RGBA float images, width * height * 4 floats each, rows from the top; alpha
    // is ignored. Throws hush::Error (InvalidArgument) naming the argument whose size
    // is wrong, and as errorMetricsFromPartials / ssimFromPartials do.
    ImageMetrics compare(std::span<const float> image, std::span<const float> reference);
    // Temporal error of two consecutive frames (same layout). Non-finite pixels are
    // left out (lastTemporalError() counts them).
    double temporalError(std::span<const float> current, std::span<const float> previous);
    const TemporalError& lastTemporalError() const { return lastTemporal_; }

    // compare()'s graph ("metrics.error", "metrics.ssim.map", "metrics.ssim.reduce"),
    // for per-pass timings; temporalError()'s graph ("metrics.temporal").
    const graph::RenderGraph& graph() const { return compareGraph_; }
    const graph::RenderGraph& temporalGraph() const { return temporalGraph_; }
    rhi::Extent2D size() const { return size_; }

private:
    // Throws hush::Error naming `argument` unless it holds width * height * 4 floats.
    void checkSize(std::span<const float> pixels, const char* argument) const;
    void upload(std::span<const float> first, std::span<const float> second);

    rhi::Device device_;
    rhi::Extent2D size_;
    MetricsSettings settings_;
    PipelineCache pipelines_;
    rhi::Texture first_, second_;   // image / current, reference / previous
    bool uploaded_[2] = {false, false};
    graph::RenderGraph compareGraph_;
    graph::RenderGraph temporalGraph_;
    graph::BufferHandle errorPartials_, ssimPartials_, temporalPartials_;
    TemporalError lastTemporal_;
};

} // namespace hush::passes
