#pragma once
// The primary surface as the filters read it: one node packs the G-buffer into
//   normalDepth  rgba32f  (unit world normal xyz, or 0 where there is no surface:
//                          a zero normal or a mesh id < 0; linear depth)
//   gradientMesh rgba32f  (dz/dx, dz/dy in depth units per pixel; mesh id; 0)
// The depth gradient is the smaller one-sided difference per axis (it feeds SVGF's
// w_z, Eq. 3, and the reprojection's depth test). The transients are named
// "<name>.normal_depth" and "<name>.gradient_mesh"; surfaceHistory() is last frame's.
#include <string>
#include <string_view>

#include <hush/passes/node_context.hpp>

namespace hush::passes {

struct Surface {
    graph::TextureHandle normalDepth;
    graph::TextureHandle gradientMesh;
};

Surface addSurfacePass(NodeContext& ctx, const std::string& name, graph::TextureHandle normal,
                       graph::TextureHandle depth, graph::TextureHandle meshId);

// Last frame's value of a Surface made by addSurfacePass: graph history handles
// (holding nothing on the first frame and after resetHistory()).
Surface surfaceHistory(NodeContext& ctx, const Surface& current);

// Declares a surface's two textures as sampled ports "<prefix>normal_depth" and
// "<prefix>gradient_mesh" (the binding names every shader that reads a surface uses).
void sampleSurface(graph::PassBuilder& b, const Surface& surface, std::string_view prefix = "");

} // namespace hush::passes
