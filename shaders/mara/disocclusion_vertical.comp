#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Mara et al. 2017 stage 5, second min pass and the radius (seed 000 Sec. 3.4):
//   m = min of the row minima within boxRadius above and below (the box minimum of c)
//   r = (1 - m) * boxRadius, times lowConfidenceScale where this pixel's c < lowConfidence
// (the paper: R = screen width / 20, "a multiplier of six where c < 1/2").
// One invocation filters a run of kRun pixels along y (mara/window_min.glsl).
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D row_min;
layout(set = 0, binding = 1) uniform texture2D temporal;   // this pixel's c in alpha
layout(set = 0, binding = 2, r32f) uniform writeonly image2D radius;

layout(push_constant) uniform Params {
    int boxRadius;
    float lowConfidence;
    float lowConfidenceScale;
} params;

int column;

float windowValue(int y) {
    return texelFetch(row_min, ivec2(column, y), 0).x;
}

#include "mara/window_min.glsl"

void main() {
    ivec2 size = imageSize(radius);
    ivec2 first = ivec2(gl_GlobalInvocationID.x, gl_GlobalInvocationID.y * kRun);
    if (!hushInside(first, size)) {
        return;
    }
    column = first.x;
    float mins[kRun];
    windowMins(first.y, params.boxRadius, size.y, mins);
    for (int k = 0; k < kRun && first.y + k < size.y; ++k) {
        ivec2 p = first + ivec2(0, k);
        float r = (1.0 - clamp(mins[k], 0.0, 1.0)) * float(params.boxRadius);
        if (texelFetch(temporal, p, 0).a < params.lowConfidence) {
            r *= params.lowConfidenceScale;
        }
        imageStore(radius, p, vec4(r, 0.0, 0.0, 0.0));
    }
}
