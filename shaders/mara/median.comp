#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Mara et al. 2017 stage 6, firefly suppression (seed 000 Sec. 3.4): a 3x3 median,
// per channel, outside the history loop, so a firefly still counts in the running
// average but never reaches the screen alone. Taps past the edge repeat the edge.
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D color;
layout(set = 0, binding = 1, rgba32f) uniform writeonly image2D median;

// The median of nine values: a fixed exchange network (Paeth 1990's 19 compare-swaps).
void sort2(inout vec3 a, inout vec3 b) {
    vec3 lo = min(a, b);
    b = max(a, b);
    a = lo;
}

void main() {
    ivec2 p = hushPixel();
    ivec2 size = imageSize(median);
    if (!hushInside(p, size)) {
        return;
    }
    vec3 v[9];
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
            v[j * 3 + i] = texelFetch(color, clamp(p + ivec2(i - 1, j - 1), ivec2(0), size - 1), 0).rgb;
        }
    }
    sort2(v[1], v[2]); sort2(v[4], v[5]); sort2(v[7], v[8]);
    sort2(v[0], v[1]); sort2(v[3], v[4]); sort2(v[6], v[7]);
    sort2(v[1], v[2]); sort2(v[4], v[5]); sort2(v[7], v[8]);
    sort2(v[0], v[3]); sort2(v[5], v[8]); sort2(v[4], v[7]);
    sort2(v[3], v[6]); sort2(v[1], v[4]); sort2(v[2], v[5]);
    sort2(v[4], v[7]); sort2(v[4], v[2]); sort2(v[6], v[4]);
    sort2(v[4], v[2]);
    imageStore(median, p, vec4(v[4], texelFetch(color, p, 0).a));
}
