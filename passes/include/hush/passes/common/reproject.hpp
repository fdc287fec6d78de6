#pragma once
// Reprojection: which of last frame's texels hold the same surface as this pixel.
// One pass decides, per pixel, once per frame; every temporal consumer (SVGF's
// accumulation, BMFR's accumulations, ...) fetches its own history through the
// decision with shaders/common/reprojection.glsl, so all of them agree on what was
// disoccluded and none repeats the geometry tests.
//
// The previous position of pixel p's centre is p + 0.5 + motion (motion = previous
// minus current position, in pixels). SVGF Sec. 4.1: a 2x2 bilinear footprint
// around it, each tap tested for the same surface (mesh id, normal, depth); the
// rejected taps' weight is redistributed over the others; if none survives, a 3x3
// footprint with equal weights over its consistent taps ("to find thin geometry");
// if none of those either, a disocclusion.
//
// Decision texture (rgba32f, transient "<name>"):
//   xy  top-left tap of the footprint + fraction: floor(xy) is the top-left tap;
//       in mode 1, fract(xy) is the bilinear position inside the 2x2 footprint
//       (xy = previous position - 0.5); in mode 2, xy is the integer top-left tap.
//       In mode 0: the clamped previous position - 0.5, for information only.
//   z   bitmask of the taps that may be used, as a float: bit (j * 2 + i) for tap
//       (i, j) of a 2x2 footprint, bit (j * 3 + i) of a 3x3 one (i right, j down).
//       A 2x2 tap is set only if it is consistent and its bilinear weight is > 0.
//   w   mode: 0 = disoccluded (no history), 1 = bilinear 2x2, 2 = 3x3 equal weights.
// Every pixel is disoccluded when PassContext::historyValid() is false (first
// frame, after RenderGraph::resetHistory()) and where the current mesh id is < 0
// (no surface). Taps outside the image are never set.
#include <cstdint>
#include <string>

#include <hush/passes/settings.hpp>
#include <hush/passes/common/surface.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

enum class ReprojectionMode : uint32_t { Disoccluded = 0, Bilinear = 1, Fallback3x3 = 2 };

struct ReprojectSettings {
    // Normal test: dot(n_tap, n) >= normalCosine. SVGF Sec. 4.1 names the test but
    // no threshold; 0.9 (25.8 degrees) accepts curved surfaces moved by a pixel and
    // rigid rotation of world normals by a frame's worth, and rejects a box's walls.
    float normalCosine = 0.9f;
    // Depth test, relative to the surface's local slope (as SVGF's w_z, Eq. 3):
    // |z_tap - z| <= depthSlopeTolerance * (|dz/dx| |o.x| + |dz/dy| |o.y|)
    //               + depthRelativeTolerance * z,
    // o = tap centre - previous position (pixels). The slope term covers the depth
    // change across the footprint; the relative term covers the change of a
    // point's view depth between frames (camera moving along or rotating about its
    // view axis), which a 2D motion vector does not carry.
    float depthSlopeTolerance = 2.0f;
    float depthRelativeTolerance = 0.02f;
    // SVGF Sec. 4.1's 3x3 retry when no 2x2 tap survives.
    bool fallback3x3 = true;
};

template <class V> void describe(V&& v, ReprojectSettings& s) {
    v.field("normalCosine", s.normalCosine, Range{-1.0, 1.0});
    v.field("depthSlopeTolerance", s.depthSlopeTolerance, Range{0.0, kUnbounded});
    v.field("depthRelativeTolerance", s.depthRelativeTolerance, Range{0.0, kUnbounded});
    v.field("fallback3x3", s.fallback3x3);
}

// Adds passes "<name>.tiles", "<name>" and "<name>.fallback" (the 3x3 fallback in
// the tiles that need it, docs/passes/reprojection.md); returns the decision texture
// (rgba32f, transient "<name>").
// `motion` is read as xy; `current` and `previous` are this and last frame's
// Surface (any textures of that layout).
graph::TextureHandle addReprojectPass(NodeContext& ctx, const std::string& name, graph::TextureHandle motion,
                                      const Surface& current, const Surface& previous,
                                      const ReprojectSettings& settings = {});
// The usual case: `previous` is surfaceHistory(ctx, current).
graph::TextureHandle addReprojectPass(NodeContext& ctx, const std::string& name, graph::TextureHandle motion,
                                      const Surface& current, const ReprojectSettings& settings = {});

// The tile list ("<name>.tiles") of the reprojection that made `decision`: the 8x8
// tiles where it tried the 3x3 fallback, the only ones that can hold mode-2 pixels.
// Invalid when `decision` is not addReprojectPass's (an imported decision, say).
// A consumer then fetches 2x2 footprints everywhere and 3x3 ones only in those
// tiles (shaders/common/footprint_tiles.glsl): passes "<name>" and "<name>.fallback".
graph::BufferHandle reprojectionFallbackTiles(const graph::RenderGraph& graph, graph::TextureHandle decision);

} // namespace hush::passes
