#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Mara et al. 2017 stage 5, second min pass and the radius (seed 000 Sec. 3.4):
//   m = min of the row minima within boxRadius above and below (the box minimum of c)
//   r = (1 - m) * boxRadius, times lowConfidenceScale where this pixel's c < lowConfidence
// (the paper: R = screen width / 20, "a multiplier of six where c < 1/2").
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

void main() {
    ivec2 p = hushPixel();
    ivec2 size = imageSize(radius);
    if (!hushInside(p, size)) {
        return;
    }
    float m = texelFetch(row_min, p, 0).x;
    int lo = max(p.y - params.boxRadius, 0), hi = min(p.y + params.boxRadius, size.y - 1);
    for (int y = lo; y <= hi; ++y) {
        m = min(m, texelFetch(row_min, ivec2(p.x, y), 0).x);
    }
    float r = (1.0 - clamp(m, 0.0, 1.0)) * float(params.boxRadius);
    if (texelFetch(temporal, p, 0).a < params.lowConfidence) {
        r *= params.lowConfidenceScale;
    }
    imageStore(radius, p, vec4(r, 0.0, 0.0, 0.0));
}
