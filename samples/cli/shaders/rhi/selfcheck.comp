#version 450
#extension GL_GOOGLE_include_directive : require
// The device self-check run by `hush info`: storage buffers, a read-write RGBA32F
// storage image, push constants and an odd-sized 2D dispatch in one kernel whose
// result the CPU can recompute.
//   y[i]  = a * x[i] + y[i]                    for i < n   (saxpy)
//   image = (rgb * a + (px, py, 1), alpha^2)   per pixel
// Keep the CPU reference in samples/cli/selfcheck.cpp in step with this file.
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std430) readonly buffer X { float x[]; };
layout(set = 0, binding = 1, std430) buffer Y { float y[]; };
layout(set = 0, binding = 2, rgba32f) uniform image2D image;

layout(push_constant) uniform Params {
    float a;
    uint n;
} params;

void main() {
    ivec2 size = imageSize(image);
    ivec2 p = hushPixel();
    if (!hushInside(p, size)) {
        return;
    }
    uint i = uint(p.y) * uint(size.x) + uint(p.x);
    if (i < params.n) {
        y[i] = params.a * x[i] + y[i];
    }
    vec4 v = imageLoad(image, p);
    imageStore(image, p, vec4(v.rgb * params.a + vec3(p, 1.0), v.a * v.a));
}
