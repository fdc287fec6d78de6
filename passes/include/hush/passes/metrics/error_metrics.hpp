#pragma once
// RMSE, relative MSE and PSNR of an image against a reference, on the GPU.
//   MSE     = mean over pixels and RGB channels of (a - b)^2
//   RMSE    = sqrt(MSE)
//   relMSE  = mean over pixels and RGB channels of (a - b)^2 / (b^2 + epsilon)
//   PSNR    = 10 log10(peak^2 / MSE) dB; +infinity when MSE == 0
// a = image, b = reference; alpha is ignored. A pixel with a non-finite (NaN, Inf)
// RGB component in either image is left out of every mean and counted.
#include <cstdint>
#include <span>
#include <string>

#include <hush/passes/metrics/metrics_settings.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

// Adds the pass "<name>": image and reference are any float format at the graph's
// output size. Returns the partial sums (partial_sums.hpp; per workgroup: squared
// error, relative error, finite pixels, non-finite pixels), marked as an output.
// Throws hush::Error (InvalidArgument) on invalid settings.
graph::BufferHandle addErrorMetricsPass(NodeContext& ctx, const std::string& name, graph::TextureHandle image,
                                        graph::TextureHandle reference, const MetricsSettings& settings = {});

struct ErrorMetrics {
    double mse = 0.0, rmse = 0.0, relMse = 0.0, psnr = 0.0;
    uint64_t pixels = 0;            // the finite pixels the means are over
    uint64_t nonFinitePixels = 0;   // left out: a NaN or Inf RGB component in either image
};

// The metrics from read-back partials. Throws hush::Error (InvalidArgument) when no
// pixel is finite, and when the fp32 sums overflowed (|a - b| beyond about 1e18;
// hush's sanitiser clamps radiance to 1e8, far below).
ErrorMetrics errorMetricsFromPartials(std::span<const float> partials, const MetricsSettings& settings = {});

} // namespace hush::passes
