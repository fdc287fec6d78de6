#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// The primary surface in the two textures every edge-stopping and reprojection test
// reads: normal_depth = (world normal xyz, linear depth) and gradient_mesh = (dz/dx,
// dz/dy, mesh id, 0). The gradient takes, per axis, the one-sided difference of
// smaller magnitude, so that a depth edge next to a pixel does not inflate its slope;
// a neighbour on another mesh (or on none) is not the same surface and is not used,
// so a one-pixel-wide blade of grass against the sky gets slope 0, not the jump to
// the far plane (which would make every depth test pass).
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D normal;
layout(set = 0, binding = 1) uniform texture2D depth;
layout(set = 0, binding = 2) uniform texture2D meshid;
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D normal_depth;
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D gradient_mesh;

float depthAt(ivec2 p) {
    return texelFetch(depth, p, 0).x;
}

// The smaller one-sided difference along `axis` to a neighbour on the same mesh; 0
// where there is none.
float slope(ivec2 p, ivec2 axis, ivec2 size) {
    float z = depthAt(p);
    float mesh = texelFetch(meshid, p, 0).x;
    ivec2 lo = p - axis, hi = p + axis;
    bool hasLo = all(greaterThanEqual(lo, ivec2(0))) && texelFetch(meshid, lo, 0).x == mesh;
    bool hasHi = all(lessThan(hi, size)) && texelFetch(meshid, hi, 0).x == mesh;
    float dLo = hasLo ? z - depthAt(lo) : 0.0;
    float dHi = hasHi ? depthAt(hi) - z : 0.0;
    if (hasLo && hasHi) {
        return abs(dLo) < abs(dHi) ? dLo : dHi;
    }
    return hasLo ? dLo : dHi;
}

void main() {
    ivec2 p = hushPixel();
    ivec2 size = imageSize(normal_depth);
    if (!hushInside(p, size)) {
        return;
    }
    // "No surface" has one encoding, a zero normal, also where only the mesh id says
    // so (< 0): the filters' per-tap surface tests then read normal_depth alone.
    vec3 n = texelFetch(normal, p, 0).xyz;
    float len = length(n);
    float mesh = texelFetch(meshid, p, 0).x;
    n = len > 1e-6 && mesh >= 0.0 ? n / len : vec3(0.0);
    imageStore(normal_depth, p, vec4(n, depthAt(p)));
    imageStore(gradient_mesh, p, vec4(slope(p, ivec2(1, 0), size), slope(p, ivec2(0, 1), size),
                                     mesh, 0.0));
}
