#version 450
#extension GL_GOOGLE_include_directive : require
// Render graph tests: dst(x, y) = seed + x * 131 + y * 7919 (r32ui), so every pixel
// of every image differs. tests/graph recomputes it on the CPU.
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, r32ui) uniform writeonly uimage2D dst;

layout(push_constant) uniform Params {
    uint seed;
} params;

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(dst))) {
        return;
    }
    imageStore(dst, p, uvec4(params.seed + uint(p.x) * 131u + uint(p.y) * 7919u));
}
