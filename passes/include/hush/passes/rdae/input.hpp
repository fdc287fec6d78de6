#pragma once
// The RDAE's input tensor (Chaitanya et al. 2017 Sec. 3.2; shaders/rdae/input.glsl):
// demodulated noisy colour^0.2, view-space normal xy, depth d/(1+d) in metres,
// roughness; 7 channels (8 with the block padding) at the padded full resolution.
#include <string>

#include <hush/passes/frame_camera.hpp>
#include <hush/passes/node_context.hpp>
#include <hush/passes/rdae/tensor.hpp>

namespace hush::passes {

inline constexpr uint32_t kRdaeInputChannels = 7;

// Adds pass "<name>". `illumination`: the demodulated colour (rgba32f); `normal`,
// `depth`, `roughness`: the sanitized G-buffer. The camera's view rotates the normals
// and its metresPerUnit scales the depth, every frame.
RdaeTensor addRdaeInputPass(NodeContext& ctx, const std::string& name, graph::TextureHandle illumination,
                            graph::TextureHandle normal, graph::TextureHandle depth, graph::TextureHandle roughness,
                            FrameCameraRef camera, const RdaeTensorFormat& format);

} // namespace hush::passes
