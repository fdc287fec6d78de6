#pragma once
// The primary surface as the filters read it: one node packs the G-buffer into
//   normalDepth  rgba32f  (unit world normal xyz, or 0 where none; linear depth)
//   gradientMesh rgba32f  (dz/dx, dz/dy in depth units per pixel; mesh id; 0)
// The depth gradient is the smaller one-sided difference per axis (it feeds SVGF's
// w_z, Eq. 3, and the reprojection's depth test). The transients are named
// "<name>.normal_depth" and "<name>.gradient_mesh", so history("<name>.normal_depth")
// is last frame's surface.
#include <string>

#include <hush/passes/node_context.hpp>

namespace hush::passes {

struct Surface {
    graph::TextureHandle normalDepth;
    graph::TextureHandle gradientMesh;
};

Surface addSurfacePass(NodeContext& ctx, const std::string& name, graph::TextureHandle normal,
                       graph::TextureHandle depth, graph::TextureHandle meshId);

// Last frame's Surface made by addSurfacePass(ctx, name, ...): graph history handles
// (invalid contents on the first frame and after resetHistory()).
Surface surfaceHistory(NodeContext& ctx, const std::string& name);

} // namespace hush::passes
