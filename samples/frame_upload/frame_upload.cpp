#include "frame_upload.hpp"

#include <cmath>
#include <cstring>

#include <hush/core/error.hpp>

namespace hush::frames {

namespace {

passes::FrameCamera::Matrix toArray(const glm::mat4& m) {
    passes::FrameCamera::Matrix out;
    std::memcpy(out.data(), &m[0][0], sizeof out);   // both column-major
    return out;
}

// How to get a layer the chain reads but the frame lacks.
std::string hintFor(passes::InputChannel c) {
    using C = passes::InputChannel;
    switch (c) {
    case C::Direct:
    case C::Indirect:
        return " (render with direct and indirect, or filter the colour as one term with a chain file: "
               "{\"base\": \"svgf\", \"settings\": {\"splitLighting\": false}})";
    case C::Matte:
    case C::Glossy:
    case C::VirtualPos:
        return " (Mara et al.'s factored terms: hush render --channels all, or add matte,glossy,virtualpos to "
               "--channels)";
    default: return " (hush render --channels all writes every layer)";
    }
}

} // namespace

tracer::Channel layerOf(passes::InputChannel channel) {
    const auto name = passes::inputChannelInfo(channel).name;
    const auto c = tracer::parseChannel(name);
    if (!c) throw Error(ErrorKind::NotFound, "no frame layer called '" + std::string(name) + "'");
    return *c;
}

std::vector<passes::InputChannel> channelsOf(const std::vector<tracer::Channel>& layers) {
    std::vector<passes::InputChannel> out;
    for (const auto& info : passes::allInputChannels())
        if (std::find(layers.begin(), layers.end(), layerOf(info.channel)) != layers.end()) out.push_back(info.channel);
    return out;
}

std::vector<passes::InputChannel> channelsOf(const tracer::Frame& frame) {
    std::vector<tracer::Channel> layers;
    for (const auto& [channel, image] : frame.channels) layers.push_back(channel);
    return channelsOf(layers);
}

passes::FrameCamera frameCamera(const tracer::Frame& frame) {
    passes::FrameCamera c;
    c.view = toArray(frame.camera.view);
    c.projection = toArray(frame.camera.projection);
    c.previousView = toArray(frame.previousCamera.view);
    c.previousProjection = toArray(frame.previousCamera.projection);
    c.position = {frame.camera.position.x, frame.camera.position.y, frame.camera.position.z};
    c.metresPerUnit = frame.metresPerUnit;
    return c;
}

void uploadFrame(passes::ChainRunner& runner, const tracer::Frame& frame, const ChannelEdit& edit) {
    auto& inputs = runner.inputs();
    const auto size = inputs.size();
    if (frame.width != size.width || frame.height != size.height)
        throw Error(ErrorKind::InvalidArgument, "frame " + std::to_string(frame.index) + " is " +
                                                    std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                                                    ", the chain runs at " + std::to_string(size.width) + "x" +
                                                    std::to_string(size.height));
    std::vector<float> pixels;
    for (const auto c : inputs.channels()) {
        const auto layer = layerOf(c);
        const uint32_t components = passes::inputChannelInfo(c).components;
        if (!frame.has(layer)) {
            if (c != passes::InputChannel::Emission)
                throw Error(ErrorKind::NotFound, "frame " + std::to_string(frame.index) + " has no '" +
                                                     std::string(passes::inputChannelInfo(c).name) +
                                                     "' layer, which chain '" + runner.chain().name() + "' reads" +
                                                     hintFor(c));
            pixels.assign(size_t(size.width) * size.height * components, 0.0f);
        } else if (!edit) {
            const auto& image = frame.get(layer);
            inputs.upload(c, image.pixels, image.channels);
            continue;
        } else {
            const auto& image = frame.get(layer);
            pixels = image.pixels;
            edit(c, pixels, image.channels);
            inputs.upload(c, pixels, image.channels);
            continue;
        }
        if (edit) edit(c, pixels, components);
        inputs.upload(c, pixels, components);
    }
    inputs.setCamera(frameCamera(frame));
}

uint64_t countNonFinite(std::span<const float> values) {
    uint64_t count = 0;
    for (const float v : values) count += std::isfinite(v) ? 0 : 1;
    return count;
}

} // namespace hush::frames
