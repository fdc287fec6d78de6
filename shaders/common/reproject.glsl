// The reprojection decision (SVGF Sec. 4.1): which of last frame's texels around
// this pixel's previous position hold the same surface. 2x2 bilinear taps first;
// if none survives, a 3x3 footprint; else a disocclusion. The encoding is in
// passes/include/hush/passes/common/reproject.hpp and common/reprojection.glsl.
//
// Two variants (common/tile_list.glsl): common/reproject.comp decides every pixel
// whose 2x2 taps settle it and lists the tiles where one needs the 3x3 fallback;
// common/reproject_fallback.comp (HUSH_LISTED_TILES) decides every pixel of those
// tiles. The fallback's nine taps thus cost only where some pixel needs them.
// Needs GL_EXT_samplerless_texture_functions in the including shader.
#ifndef HUSH_COMMON_REPROJECT_GLSL
#define HUSH_COMMON_REPROJECT_GLSL
#include "common/grid.glsl"
#include "common/reprojection.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
// One tile is one workgroup (common/tile_list.glsl).
const uvec2 kTile = uvec2(8, 8);

layout(set = 0, binding = 0) uniform texture2D motion;
layout(set = 0, binding = 1) uniform texture2D normal_depth;
layout(set = 0, binding = 2) uniform texture2D gradient_mesh;
layout(set = 0, binding = 3) uniform texture2D previous_normal_depth;
layout(set = 0, binding = 4) uniform texture2D previous_gradient_mesh;
layout(set = 0, binding = 5, rgba32f) uniform writeonly image2D reprojection;
#define HUSH_TILE_LIST_BINDING 6
#include "common/tile_list.glsl"

layout(push_constant) uniform Params {
    float normalCosine;
    float depthSlopeTolerance;
    float depthRelativeTolerance;
    uint fallback3x3;
    uint historyValid;
} params;

// This pixel's surface: what every tap is compared with.
struct Centre {
    vec3 normal;
    float depth;
    vec2 gradient;
    float meshId;
};

// Same surface? Mesh ids equal, normals within the cone, depth within the slope-
// and depth-relative tolerance. `offset` = tap centre - previous position, pixels.
// Written as comparisons without division, so no input makes a NaN decide, and
// without branches: a tap off the image is fetched clamped and fails `inside`
// (lavapipe runs this about 15 % faster than early returns; docs/benchmarks.md).
bool consistent(Centre c, ivec2 tap, vec2 offset, ivec2 size) {
    bool inside = hushInside(tap, size);
    ivec2 t = clamp(tap, ivec2(0), size - 1);
    vec4 nd = texelFetch(previous_normal_depth, t, 0);
    float meshId = texelFetch(previous_gradient_mesh, t, 0).z;
    float slope = abs(c.gradient.x) * abs(offset.x) + abs(c.gradient.y) * abs(offset.y);
    float tolerance = params.depthSlopeTolerance * slope + params.depthRelativeTolerance * abs(c.depth);
    bool sameMesh = meshId == c.meshId;
    bool facing = dot(nd.xyz, c.normal) >= params.normalCosine;
    bool near = abs(nd.w - c.depth) <= tolerance;
    return inside && sameMesh && facing && near;
}

void main() {
    ivec2 size = imageSize(reprojection);
    ivec2 p = hushTilePixel(size, kTile);
    if (!hushInside(p, size)) {
        return;
    }
    vec2 pos = vec2(p) + texelFetch(motion, p, 0).xy;   // previous position - 0.5
    vec2 lo = vec2(-2.0), hi = vec2(size) + 1.0;
    // Beyond [-2, size + 1] no tap of either footprint is on screen; NaN fails too.
    bool near = all(greaterThanEqual(pos, lo)) && all(lessThanEqual(pos, hi));
    vec2 shown = vec2(pos.x >= lo.x ? min(pos.x, hi.x) : lo.x, pos.y >= lo.y ? min(pos.y, hi.y) : lo.y);

    vec4 nd = texelFetch(normal_depth, p, 0);
    vec4 gm = texelFetch(gradient_mesh, p, 0);
    Centre c = Centre(nd.xyz, nd.w, gm.xy, gm.z);
    if (params.historyValid == 0u || !near || c.meshId < 0.0) {
        imageStore(reprojection, p, vec4(shown, 0.0, float(kReprojectDisoccluded)));
        return;
    }

    // 2x2: a tap counts if it is the same surface and has a positive bilinear weight.
    vec2 base = floor(pos);
    vec2 frac = pos - base;
    uint mask = 0u;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            float w = (i == 0 ? 1.0 - frac.x : frac.x) * (j == 0 ? 1.0 - frac.y : frac.y);
            vec2 offset = vec2(i, j) - frac;
            bool same = consistent(c, ivec2(base) + ivec2(i, j), offset, size);
            mask |= w > 0.0 && same ? 1u << uint(j * 2 + i) : 0u;
        }
    }
    if (mask != 0u) {
        imageStore(reprojection, p, vec4(pos, float(mask), float(kReprojectBilinear)));
        return;
    }

    // 3x3 around the texel that holds the previous position: in the listed tiles only.
    if (params.fallback3x3 != 0u) {
#ifndef HUSH_LISTED_TILES
        hushListTile(size, kTile);
        return;
#else
        vec2 topLeft = floor(pos + 0.5) - 1.0;
        for (int j = 0; j < 3; ++j) {
            for (int i = 0; i < 3; ++i) {
                vec2 offset = topLeft + vec2(i, j) - pos;
                if (consistent(c, ivec2(topLeft) + ivec2(i, j), offset, size)) {
                    mask |= 1u << uint(j * 3 + i);
                }
            }
        }
        if (mask != 0u) {
            imageStore(reprojection, p, vec4(topLeft, float(mask), float(kReprojectFallback3x3)));
            return;
        }
#endif
    }
    imageStore(reprojection, p, vec4(shown, 0.0, float(kReprojectDisoccluded)));
}

#endif
