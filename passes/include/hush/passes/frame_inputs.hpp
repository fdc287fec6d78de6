#pragma once
// FrameInputs: the application-side textures that hold one frame's inputs, uploaded
// from CPU float images (a tracer frame, an EXR from another renderer) and imported
// into a chain's graph. Uploading waits for the copy: this is the path for tools,
// tests and offline runs; an engine imports its own G-buffer textures instead.
#include <span>
#include <string>
#include <vector>

#include <hush/graph/render_graph.hpp>
#include <hush/passes/denoise_inputs.hpp>
#include <hush/rhi/device.hpp>

namespace hush::passes {

class FrameInputs {
public:
    FrameInputs(rhi::Device device, rhi::Extent2D size, std::vector<InputChannel> channels);

    // `pixels` holds width * height * `components` floats, rows from the top. Missing
    // components are filled (0, alpha 1); extra ones are dropped. Throws hush::Error
    // naming the channel when it is not one of this object's or the size is wrong.
    void upload(InputChannel channel, std::span<const float> pixels, uint32_t components);
    // The frame's camera, read by the chains that need one (FrameCamera); validated.
    void setCamera(const FrameCamera& camera);
    // Imports every channel as "input.<name>" (read-only, sampled) into `graph`, and
    // hands out the camera (its values change with every setCamera).
    DenoiseInputs import(graph::RenderGraph& graph) const;

    rhi::Extent2D size() const { return size_; }
    const std::vector<InputChannel>& channels() const { return channels_; }
    const rhi::Texture& texture(InputChannel channel) const;

private:
    rhi::Device device_;
    rhi::Extent2D size_;
    std::vector<InputChannel> channels_;
    std::array<rhi::Texture, kInputChannelCount> textures_;
    std::array<bool, kInputChannelCount> uploaded_{};
    std::vector<float> staging_;
    std::shared_ptr<FrameCamera> camera_ = std::make_shared<FrameCamera>();
};

} // namespace hush::passes
