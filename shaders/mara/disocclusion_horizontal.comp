#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Mara et al. 2017 stage 5, first of the "two simple 1D min passes" (seed 000 Sec.
// 3.4): the smallest temporal confidence c (alpha of the matte temporal output) within
// `boxRadius` pixels left and right.
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D temporal;   // c in alpha
layout(set = 0, binding = 1, r32f) uniform writeonly image2D row_min;

layout(push_constant) uniform Params {
    int boxRadius;
} params;

void main() {
    ivec2 p = hushPixel();
    ivec2 size = imageSize(row_min);
    if (!hushInside(p, size)) {
        return;
    }
    float m = texelFetch(temporal, p, 0).a;
    int lo = max(p.x - params.boxRadius, 0), hi = min(p.x + params.boxRadius, size.x - 1);
    for (int x = lo; x <= hi; ++x) {
        m = min(m, texelFetch(temporal, ivec2(x, p.y), 0).a);
    }
    imageStore(row_min, p, vec4(m, 0.0, 0.0, 0.0));
}
