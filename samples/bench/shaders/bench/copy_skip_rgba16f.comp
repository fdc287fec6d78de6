#version 450
#extension GL_GOOGLE_include_directive : require
// The graph benchmark's compile-time chain (samples/bench/graph_bench.cpp): a copy
// that also reads `skip`, an earlier result, so that lifetimes and barriers are
// shaped as a pass reading two inputs would shape them. `skip` is unconnected (a
// placeholder) on the first passes; it adds nothing, so the copy stays exact.
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba16f) uniform readonly image2D src;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2D dst;
layout(set = 0, binding = 2, rgba16f) uniform readonly image2D skip;

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(dst))) {
        return;
    }
    // imageSize, not imageLoad: the binding is used (kept by the compiler) but never read.
    vec4 unused = vec4(imageSize(skip).x < 0 ? 1.0 : 0.0);
    imageStore(dst, p, imageLoad(src, p) + unused);
}
