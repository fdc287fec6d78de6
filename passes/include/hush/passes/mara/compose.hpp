#pragma once
// Mara et al. 2017's composite (seed 000 Sec. 3.1-3.3, Eq. 9, 10): the filtered
// indirect terms with the material put back at the mirror direction w_s,
//   radiance = direct + (1 - F)^2 * albedo * matte + F * glossy,
//   F = Schlick(F0 = specular, cos = n . v) = F0 + (1 - F0) (1 - n.v)^5, 0 where F0 = 0,
// v the direction to the camera. Without `glossy` (an invalid handle) its term is
// left out, and the graph culls whatever only fed it.
#include <string>

#include <hush/passes/common/surface.hpp>
#include <hush/passes/frame_camera.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

struct MaraComposeInputs {
    graph::TextureHandle direct;     // noise-free direct light, emission included
    graph::TextureHandle matte;      // filtered matte irradiance
    graph::TextureHandle glossy;     // filtered glossy term, or invalid
    graph::TextureHandle albedo;
    graph::TextureHandle specular;   // F0
    Surface surface;
    graph::TextureHandle position;
};

// Adds pass "<name>"; returns radiance, rgba32f "<name>". The camera position comes
// from `camera` each frame.
graph::TextureHandle addMaraComposePass(NodeContext& ctx, const std::string& name, const MaraComposeInputs& in,
                                        FrameCameraRef camera);

} // namespace hush::passes
