#include <hush/passes/metrics/metrics_settings.hpp>

#include <cmath>
#include <string>

#include <hush/core/error.hpp>

namespace hush::passes {

namespace {
void requirePositive(double value, const char* name) {
    if (!(std::isfinite(value) && value > 0.0))
        throw Error(ErrorKind::InvalidArgument, std::string("metrics settings: ") + name + " is " +
                                                    std::to_string(value) + "; it must be a positive finite number");
}
} // namespace

void validateMetricsSettings(const MetricsSettings& settings) {
    requirePositive(settings.psnrPeak, "psnrPeak");
    requirePositive(settings.relMseEpsilon, "relMseEpsilon");
    requirePositive(settings.ssimK1, "ssimK1");
    requirePositive(settings.ssimK2, "ssimK2");
    requirePositive(settings.ssimDynamicRange, "ssimDynamicRange");
    requirePositive(settings.ssimSigma, "ssimSigma");
    // C1 and C2 are the SSIM denominators' floors; they must stay positive in fp32.
    requirePositive(float(settings.ssimC1()), "ssimC1 = (ssimK1 * ssimDynamicRange)^2");
    requirePositive(float(settings.ssimC2()), "ssimC2 = (ssimK2 * ssimDynamicRange)^2");
}

} // namespace hush::passes
