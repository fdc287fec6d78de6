#pragma once
// The constants of hush's image-quality metrics (docs/passes/metrics.md). Images are
// display-space RGB(A) floats, typically in [0, 1]; alpha is never compared.

namespace hush::passes {

struct MetricsSettings {
    // PSNR = 10 log10(peak^2 / MSE); 1 for display-space images in [0, 1].
    double psnrPeak = 1.0;
    // Relative MSE = mean of (a - b)^2 / (b^2 + epsilon) over pixels and RGB, b the
    // reference (the definition of Rousselle, Knaus and Zwicker 2011, used by most
    // denoising papers since); epsilon keeps dark reference pixels from dominating.
    float relMseEpsilon = 0.01f;
    // SSIM (Wang, Bovik, Sheikh, Simoncelli 2004, Sec. III-B/C): C1 = (K1 L)^2,
    // C2 = (K2 L)^2 with L the dynamic range of the values; 11 x 11 Gaussian window
    // of standard deviation 1.5 pixels, normalised to unit sum.
    float ssimK1 = 0.01f;
    float ssimK2 = 0.03f;
    float ssimDynamicRange = 1.0f;
    float ssimSigma = 1.5f;

    double ssimC1() const { return double(ssimK1) * ssimDynamicRange * ssimK1 * ssimDynamicRange; }
    double ssimC2() const { return double(ssimK2) * ssimDynamicRange * ssimK2 * ssimDynamicRange; }
};

// Throws hush::Error (InvalidArgument) naming the first setting that is not a
// positive finite number (each one guards a division or a logarithm).
void validateMetricsSettings(const MetricsSettings& settings);

} // namespace hush::passes
