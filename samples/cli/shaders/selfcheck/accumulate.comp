#version 450
#extension GL_GOOGLE_include_directive : require
// dst = current + history, with history counted only when it holds last frame's
// value. The render-graph self-check's use of a history resource (hush info).
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba32f) uniform readonly image2D current;
layout(set = 0, binding = 1, rgba32f) uniform readonly image2D history;
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D dst;
layout(push_constant) uniform Params {
    uint historyValid;
} params;

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(dst))) {
        return;
    }
    vec4 sum = imageLoad(current, p);
    if (params.historyValid != 0u) {
        sum += imageLoad(history, p);
    }
    imageStore(dst, p, sum);
}
