#pragma once
// The per-pixel inputs a chain reads, named as the frame format's layers
// (docs/frame-format.md), and the GPU format each is held in.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <hush/graph/handles.hpp>
#include <hush/passes/frame_camera.hpp>
#include <hush/rhi/format.hpp>

namespace hush::passes {

enum class InputChannel : uint8_t {
    Color,      // noisy radiance, direct + indirect
    Direct,
    Indirect,
    Albedo,     // primary hit diffuse reflectance
    Specular,   // primary hit F0
    Normal,     // world-space unit normal
    Position,   // world-space position
    Depth,      // linear view depth
    Motion,     // previous pixel minus current pixel
    Roughness,  // GGX alpha
    MeshId,     // float; -1 where no surface
    Emission,   // radiance the primary hit emits (part of direct / color), noise-free
    Matte,      // Mara et al.'s matte indirect term, F and m factored out (seed 000 Eq. 9)
    Glossy,     // Mara et al.'s glossy indirect term, F factored out (Eq. 10)
    VirtualPos, // world-space reflected virtual position (Mara et al. Sec. 3.4)
};
inline constexpr size_t kInputChannelCount = 15;

struct InputChannelInfo {
    InputChannel channel;
    std::string_view name;       // the frame format's layer name ("meshid")
    rhi::Format format;          // how it is held on the GPU
    uint32_t components;         // meaningful components (rgb: 3)
};
const InputChannelInfo& inputChannelInfo(InputChannel channel);
std::span<const InputChannelInfo> allInputChannels();
std::optional<InputChannel> parseInputChannel(std::string_view name);

// Graph handles of a frame's inputs; a channel a chain does not need may be invalid.
// `camera` is the frame's camera (null when the frames come without one).
struct DenoiseInputs {
    std::array<graph::TextureHandle, kInputChannelCount> channels{};
    FrameCameraRef camera;
    graph::TextureHandle& operator[](InputChannel c) { return channels[size_t(c)]; }
    graph::TextureHandle operator[](InputChannel c) const { return channels[size_t(c)]; }
    bool has(InputChannel c) const { return channels[size_t(c)].valid(); }
};

} // namespace hush::passes
