#version 450
#extension GL_GOOGLE_include_directive : require
// Render graph tests: dst = src + add (r32ui).
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, r32ui) uniform readonly uimage2D src;
layout(set = 0, binding = 1, r32ui) uniform writeonly uimage2D dst;

layout(push_constant) uniform Params {
    uint add;
} params;

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(dst))) {
        return;
    }
    imageStore(dst, p, uvec4(imageLoad(src, p).x + params.add));
}
