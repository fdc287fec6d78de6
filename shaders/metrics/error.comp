#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Error metrics' partial sums (passes/metrics/error_metrics.hpp). Per pixel, over
// the RGB channels c (alpha ignored), with a = image, b = reference:
//   squared error   sum_c (a_c - b_c)^2                       (RMSE, PSNR)
//   relative error  sum_c (a_c - b_c)^2 / (b_c^2 + epsilon)   (relative MSE)
// A pixel with a non-finite RGB component in either image adds nothing and is
// counted instead. Partial: (squared, relative, finite pixels, non-finite pixels).
#include "metrics/reduce.glsl"

layout(set = 0, binding = 0) uniform texture2D image;
layout(set = 0, binding = 1) uniform texture2D reference;

layout(push_constant) uniform Params {
    float epsilon;   // relative MSE's denominator offset (> 0: the division is guarded)
} params;

void main() {
    const ivec2 size = textureSize(image, 0);
    const ivec2 stride = hushGridStride();
    vec4 sums = vec4(0.0);
    for (int y = hushGridStart().y; y < size.y; y += stride.y) {
        for (int x = hushGridStart().x; x < size.x; x += stride.x) {
            const vec3 a = texelFetch(image, ivec2(x, y), 0).rgb;
            const vec3 b = texelFetch(reference, ivec2(x, y), 0).rgb;
            if (!hushAllFinite(a) || !hushAllFinite(b)) {
                sums.w += 1.0;
                continue;
            }
            const vec3 d = a - b;
            const vec3 squared = d * d;
            sums.x += squared.r + squared.g + squared.b;
            const vec3 relative = squared / (b * b + params.epsilon);
            sums.y += relative.r + relative.g + relative.b;
            sums.z += 1.0;
        }
    }
    hushStorePartial(sums);
}
