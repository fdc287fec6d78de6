#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Mara et al. 2017 stage 5, first of the "two simple 1D min passes" (seed 000 Sec.
// 3.4): the smallest temporal confidence c (alpha of the matte temporal output) within
// `boxRadius` pixels left and right. One invocation filters a run of kRun pixels
// along x (mara/window_min.glsl).
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D temporal;   // c in alpha
layout(set = 0, binding = 1, r32f) uniform writeonly image2D row_min;

layout(push_constant) uniform Params {
    int boxRadius;
} params;

int row;

float windowValue(int x) {
    return texelFetch(temporal, ivec2(x, row), 0).a;
}

#include "mara/window_min.glsl"

void main() {
    ivec2 size = imageSize(row_min);
    ivec2 first = ivec2(gl_GlobalInvocationID.x * kRun, gl_GlobalInvocationID.y);
    if (!hushInside(first, size)) {
        return;
    }
    row = first.y;
    float mins[kRun];
    windowMins(first.x, params.boxRadius, size.x, mins);
    for (int k = 0; k < kRun && first.x + k < size.x; ++k) {
        imageStore(row_min, first + ivec2(k, 0), vec4(mins[k], 0.0, 0.0, 0.0));
    }
}
