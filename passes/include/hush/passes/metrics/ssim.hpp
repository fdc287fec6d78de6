#pragma once
// Mean SSIM (Wang, Bovik, Sheikh, Simoncelli 2004, Eq. 13-17) of an image against a
// reference, on the GPU: an 11 x 11 Gaussian window (sigma 1.5, normalised), SSIM
// per RGB channel averaged over the channels, the mean over window positions.
//
// Window positions: along an axis of at least 11 pixels, only the "valid" ones
// whose window lies inside the image (no padding, as Wang's ssim_index.m); along an
// axis of fewer than 11 pixels, every pixel, with the window clipped to the image
// and renormalised over the taps that remain. So a 1x1 image has one position whose
// window is the pixel itself (SSIM = luminance term), and identical images give 1.
// A position whose window holds a non-finite RGB value in either image is left out
// of the mean and counted. The (co)variances are computed about the window mean
// (Eq. 15-16), not as E[x^2] - mu^2, so large values (1e6) do not cancel in fp32.
#include <cstdint>
#include <span>
#include <string>

#include <hush/passes/metrics/metrics_settings.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

struct SsimOutputs {
    // rgba32f at output size: (SSIM averaged over RGB, 1, 0, 0) at a counted window
    // position, (0, 0, 1, 0) at an excluded one, 0 elsewhere. Transient: mark it as an
    // output to read it.
    graph::TextureHandle map;
    // Partial sums of the map (partial_sums.hpp), marked as an output.
    graph::BufferHandle partials;
};

// Adds "<name>.map" and "<name>.reduce". Inputs: any float format at output size.
// Throws hush::Error (InvalidArgument) on invalid settings.
SsimOutputs addSsimPass(NodeContext& ctx, const std::string& name, graph::TextureHandle image,
                        graph::TextureHandle reference, const MetricsSettings& settings = {});

struct SsimResult {
    double ssim = 0.0;              // mean over counted window positions
    uint64_t windows = 0;           // counted window positions
    uint64_t excludedWindows = 0;   // left out: a non-finite value inside the window
};

// The mean SSIM from read-back partials. Throws hush::Error (InvalidArgument) when
// every window was excluded, and when a sum is not finite (fp32 overflow of mu^2:
// values beyond about 1e18).
SsimResult ssimFromPartials(std::span<const float> partials);

} // namespace hush::passes
