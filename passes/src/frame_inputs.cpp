#include <hush/passes/frame_inputs.hpp>

#include <algorithm>
#include <cstring>

#include <hush/core/error.hpp>

namespace hush::passes {

FrameInputs::FrameInputs(rhi::Device device, rhi::Extent2D size, std::vector<InputChannel> channels)
    : device_(std::move(device)), size_(size), channels_(std::move(channels)) {
    if (size.width == 0 || size.height == 0)
        throw Error(ErrorKind::InvalidArgument, "frame inputs: size " + std::to_string(size.width) + "x" +
                                                    std::to_string(size.height) + " is empty");
    for (auto c : channels_) {
        const auto& info = inputChannelInfo(c);
        if (textures_[size_t(c)]) continue;
        textures_[size_t(c)] = device_.createTexture(
            {.label = "input." + std::string(info.name),
             .size = size_,
             .format = info.format,
             .usage = rhi::TextureUsage::TextureBinding | rhi::TextureUsage::StorageBinding |
                      rhi::TextureUsage::CopyDst | rhi::TextureUsage::CopySrc});
    }
}

const rhi::Texture& FrameInputs::texture(InputChannel channel) const {
    const auto& t = textures_[size_t(channel)];
    if (!t)
        throw Error(ErrorKind::InvalidArgument,
                    "frame inputs: channel '" + std::string(inputChannelInfo(channel).name) + "' was not requested");
    return t;
}

void FrameInputs::upload(InputChannel channel, std::span<const float> pixels, uint32_t components) {
    const auto& info = inputChannelInfo(channel);
    const auto& texture = this->texture(channel);
    const size_t count = size_t(size_.width) * size_.height;
    if (components == 0 || pixels.size() != count * components)
        throw Error(ErrorKind::InvalidArgument,
                    "frame inputs: channel '" + std::string(info.name) + "' got " + std::to_string(pixels.size()) +
                        " floats for " + std::to_string(size_.width) + "x" + std::to_string(size_.height) + "x" +
                        std::to_string(components) + " (expected " + std::to_string(count * components) + ")");
    const uint32_t texelComponents = rhi::formatInfo(info.format).channels;
    staging_.assign(count * texelComponents, 0.0f);
    const uint32_t copied = std::min(components, texelComponents);
    for (size_t i = 0; i < count; ++i) {
        float* dst = staging_.data() + i * texelComponents;
        std::memcpy(dst, pixels.data() + i * components, copied * sizeof(float));
        if (texelComponents == 4 && copied < 4) dst[3] = 1.0f;
    }
    auto& uploaded = uploaded_[size_t(channel)];
    device_.queue().writeTexture({.texture = texture,
                                  .data = std::as_bytes(std::span<const float>(staging_)),
                                  .before = uploaded ? rhi::ResourceState::SampledRead : rhi::ResourceState::Undefined,
                                  .after = rhi::ResourceState::SampledRead});
    uploaded = true;
}

void FrameInputs::setCamera(const FrameCamera& camera) {
    validate(camera);
    *camera_ = camera;
}

DenoiseInputs FrameInputs::import(graph::RenderGraph& graph) const {
    DenoiseInputs inputs;
    inputs.camera = camera_;
    for (auto c : channels_)
        inputs[c] = graph.importTexture("input." + std::string(inputChannelInfo(c).name), textures_[size_t(c)]);
    return inputs;
}

} // namespace hush::passes
