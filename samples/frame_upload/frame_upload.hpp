#pragma once
// A frame (docs/frame-format.md, as the tracer reads it) into a chain's inputs: every
// channel the chain reads, and the camera. Errors name the frame, the missing layer,
// the chain, and how to render it.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <hush/passes/chain_runner.hpp>
#include <hush/tracer/frame.hpp>

namespace hush::frames {

// The frame-format layer of an input channel ("matte" -> Channel::Matte).
tracer::Channel layerOf(passes::InputChannel channel);
// The input channels a frame with these layers can feed.
std::vector<passes::InputChannel> channelsOf(const std::vector<tracer::Channel>& layers);
std::vector<passes::InputChannel> channelsOf(const tracer::Frame& frame);

passes::FrameCamera frameCamera(const tracer::Frame& frame);

// Called with each channel's pixels before upload (tests inject faults with it).
using ChannelEdit = std::function<void(passes::InputChannel, std::vector<float>& pixels, uint32_t components)>;

// Uploads every channel runner.inputs() holds, and the camera. A missing emission
// layer uploads zeros (a renderer that does not split emission off: none to take
// out); any other missing layer is hush::Error (NotFound).
void uploadFrame(passes::ChainRunner& runner, const tracer::Frame& frame, const ChannelEdit& edit = {});

// Non-finite values in a chain's read-back output: the CLI, the soak run and the
// chain tests count them in every output they read.
uint64_t countNonFinite(std::span<const float> values);

} // namespace hush::frames
