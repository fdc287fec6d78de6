#version 450
#extension GL_GOOGLE_include_directive : require
// A per-pixel function the CPU recomputes in tests/rhi/test_compute.cpp:
//   dst.rgb = src.rgb * scale.rgb + bias.rgb,   dst.a = sqrt(|src.a|) + bias.a
//   luminance[y * width + x] = dot(src.rgb, (0.2126, 0.7152, 0.0722)) + x - 0.5 * y
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba32f) uniform readonly image2D srcImage;
layout(set = 0, binding = 1, rgba32f) uniform writeonly image2D dstImage;
layout(set = 0, binding = 2, std430) writeonly buffer Luminance { float luminance[]; };

layout(push_constant) uniform Params {
    vec4 scale;
    vec4 bias;
    uvec2 size;
} params;

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, ivec2(params.size))) {
        return;
    }
    vec4 c = imageLoad(srcImage, p);
    vec4 o;
    o.rgb = c.rgb * params.scale.rgb + params.bias.rgb;
    o.a = sqrt(abs(c.a)) + params.bias.a;
    imageStore(dstImage, p, o);
    luminance[uint(p.y) * params.size.x + uint(p.x)] =
        dot(c.rgb, vec3(0.2126, 0.7152, 0.0722)) + float(p.x) - 0.5 * float(p.y);
}
