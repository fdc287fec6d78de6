#version 450
#extension GL_GOOGLE_include_directive : require
// Render graph tests: one step of a chain of integer functions (r32ui, exact, so a
// texel that aliasing or a missing barrier corrupted shows up as a wrong value):
//   dst = ((a * mulA) ^ (b * mulB + add)) + (a >> rotate) + x * 3 + y * 5
// tests/graph/graph_test_util.hpp's combineReference is the CPU version.
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, r32ui) uniform readonly uimage2D a;
layout(set = 0, binding = 1, r32ui) uniform readonly uimage2D b;
layout(set = 0, binding = 2, r32ui) uniform writeonly uimage2D dst;

layout(push_constant) uniform Params {
    uint mulA;
    uint mulB;
    uint add;
    uint rotate;
} params;

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(dst))) {
        return;
    }
    uint va = imageLoad(a, p).x;
    uint vb = imageLoad(b, p).x;
    uint v = ((va * params.mulA) ^ (vb * params.mulB + params.add)) + (va >> params.rotate) + uint(p.x) * 3u +
             uint(p.y) * 5u;
    imageStore(dst, p, uvec4(v));
}
