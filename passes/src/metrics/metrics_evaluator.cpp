#include <hush/passes/metrics/metrics_evaluator.hpp>

#include <string>

#include <hush/passes/metrics/partial_sums.hpp>
#include <hush/core/error.hpp>

namespace hush::passes {

namespace {
rhi::Extent2D checkedSize(rhi::Extent2D size) {
    if (size.width == 0 || size.height == 0)
        throw Error(ErrorKind::InvalidArgument, "metrics evaluator: size " + std::to_string(size.width) + "x" +
                                                    std::to_string(size.height) + " is empty");
    return size;
}

rhi::Texture makeInput(const rhi::Device& device, rhi::Extent2D size, const char* label) {
    return device.createTexture({.label = label,
                                 .size = size,
                                 .format = rhi::Format::RGBA32Float,
                                 .usage = rhi::TextureUsage::TextureBinding | rhi::TextureUsage::CopyDst});
}
} // namespace

MetricsEvaluator::MetricsEvaluator(rhi::Device device, rhi::Extent2D size, const MetricsSettings& settings)
    : device_(std::move(device)),
      size_(checkedSize(size)),
      settings_(settings),
      pipelines_(device_),
      compareGraph_(device_, {.label = "metrics.compare"}),
      temporalGraph_(device_, {.label = "metrics.temporal"}) {
    validateMetricsSettings(settings_);
    first_ = makeInput(device_, size_, "metrics.first");
    second_ = makeInput(device_, size_, "metrics.second");

    compareGraph_.setOutputSize(size_);
    NodeContext compare{compareGraph_, pipelines_};
    const auto image = compareGraph_.importTexture("image", first_);
    const auto reference = compareGraph_.importTexture("reference", second_);
    errorPartials_ = addErrorMetricsPass(compare, "metrics.error", image, reference, settings_);
    ssimPartials_ = addSsimPass(compare, "metrics.ssim", image, reference, settings_).partials;

    temporalGraph_.setOutputSize(size_);
    NodeContext temporal{temporalGraph_, pipelines_};
    const auto current = temporalGraph_.importTexture("current", first_);
    const auto previous = temporalGraph_.importTexture("previous", second_);
    temporalPartials_ = addTemporalErrorPass(temporal, "metrics.temporal", current, previous);
}

void MetricsEvaluator::checkSize(std::span<const float> pixels, const char* argument) const {
    const size_t expected = size_t(size_.width) * size_.height * 4;
    if (pixels.size() != expected)
        throw Error(ErrorKind::InvalidArgument,
                    std::string("metrics evaluator: '") + argument + "' has " + std::to_string(pixels.size()) +
                        " floats; a " + std::to_string(size_.width) + "x" + std::to_string(size_.height) +
                        " RGBA image has " + std::to_string(expected));
}

void MetricsEvaluator::upload(std::span<const float> first, std::span<const float> second) {
    const rhi::Texture* textures[2] = {&first_, &second_};
    const std::span<const float> pixels[2] = {first, second};
    for (int i = 0; i < 2; ++i) {
        device_.queue().writeTexture(
            {.texture = *textures[i],
             .data = std::as_bytes(pixels[i]),
             .before = uploaded_[i] ? rhi::ResourceState::SampledRead : rhi::ResourceState::Undefined,
             .after = rhi::ResourceState::SampledRead});
        uploaded_[i] = true;
    }
}

ImageMetrics MetricsEvaluator::compare(std::span<const float> image, std::span<const float> reference) {
    checkSize(image, "image");
    checkSize(reference, "reference");
    upload(image, reference);
    compareGraph_.execute();
    compareGraph_.waitIdle();
    const auto error = errorMetricsFromPartials(readPartials(device_, compareGraph_, errorPartials_), settings_);
    const auto ssim = ssimFromPartials(readPartials(device_, compareGraph_, ssimPartials_));
    return {.rmse = error.rmse,
            .relMse = error.relMse,
            .psnr = error.psnr,
            .ssim = ssim.ssim,
            .nonFinitePixels = error.nonFinitePixels,
            .excludedSsimWindows = ssim.excludedWindows};
}

double MetricsEvaluator::temporalError(std::span<const float> current, std::span<const float> previous) {
    checkSize(current, "current");
    checkSize(previous, "previous");
    upload(current, previous);
    temporalGraph_.execute();
    temporalGraph_.waitIdle();
    lastTemporal_ = temporalErrorFromPartials(readPartials(device_, temporalGraph_, temporalPartials_));
    return lastTemporal_.error;
}

} // namespace hush::passes
