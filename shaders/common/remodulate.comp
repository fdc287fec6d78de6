#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// radiance = sum of the filtered illumination terms * demodulationFactor(albedo)
// + emission: the inverse of common/demodulate.comp, over one or two terms.
#include "common/grid.glsl"
#include "common/demodulation.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D a;
layout(set = 0, binding = 1) uniform texture2D b;
layout(set = 0, binding = 2) uniform texture2D albedo;
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D radiance;
layout(set = 0, binding = 4) uniform texture2D emission;   // read when hasEmission

layout(push_constant) uniform Params {
    float eps;
    uint termCount;   // 1: b is not read
    uint hasEmission;
} params;

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(radiance))) {
        return;
    }
    vec3 sum = texelFetch(a, p, 0).rgb;
    if (params.termCount > 1u) {
        sum += texelFetch(b, p, 0).rgb;
    }
    vec3 factor = demodulationFactor(texelFetch(albedo, p, 0).rgb, params.eps);
    vec3 result = sum * factor;
    if (params.hasEmission != 0u) {
        result += texelFetch(emission, p, 0).rgb;
    }
    imageStore(radiance, p, vec4(result, 1.0));
}
