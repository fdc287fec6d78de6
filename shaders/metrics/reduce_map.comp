#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Sums every texel of a map (the SSIM map: value, counted, excluded, 0) into the
// fixed grid of partials (metrics/reduce.glsl).
#include "metrics/reduce.glsl"

layout(set = 0, binding = 0) uniform texture2D map;

void main() {
    const ivec2 size = textureSize(map, 0);
    const ivec2 stride = hushGridStride();
    vec4 sums = vec4(0.0);
    for (int y = hushGridStart().y; y < size.y; y += stride.y) {
        for (int x = hushGridStart().x; x < size.x; x += stride.x) {
            sums += texelFetch(map, ivec2(x, y), 0);
        }
    }
    hushStorePartial(sums);
}
