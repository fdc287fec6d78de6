#version 450
#extension GL_GOOGLE_include_directive : require
// Bandwidth probe: one imageLoad and one imageStore per texel of an RGBA16F
// storage texture (8 bytes read + 8 written). No arithmetic, so the time is the
// memory system's. Used by samples/bench/bandwidth.cpp.
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba16f) uniform readonly image2D src;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2D dst;

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(dst))) {
        return;
    }
    imageStore(dst, p, imageLoad(src, p));
}
