#version 450
#extension GL_GOOGLE_include_directive : require
// dst = src * scale + bias, per channel. A render-graph self-check step (hush info).
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba32f) uniform readonly image2D src;
layout(set = 0, binding = 1, rgba32f) uniform writeonly image2D dst;
layout(push_constant) uniform Params {
    float scale;
    float bias;
} params;

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(dst))) {
        return;
    }
    imageStore(dst, p, imageLoad(src, p) * params.scale + params.bias);
}
