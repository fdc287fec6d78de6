#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// HDR radiance -> display values in [0, 1], linear (passes/common/tonemap.hpp: the
// curves, their sources and their CPU twins in passes/src/common/tonemap.cpp).
#include "common/grid.glsl"
#include "common/color_spaces.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D radiance;
layout(set = 0, binding = 1, rgba32f) uniform writeonly image2D display;

layout(push_constant) uniform Params {
    uint op;          // TonemapOperator: 0 ACES fit, 1 Reinhard on luminance, 2 Reinhard per channel
    float exposure;
} params;

// Narkowicz 2016's fit reaches 1 at x ~ 7.24, so clamping the input to 64 changes
// nothing but keeps x^2 finite; its denominator has no real root (d^2 < 4ce).
const float kAcesInputMax = 64.0;
// x / (1 + x) is 1 in fp32 long before this; the clamp keeps the luminance finite.
const float kReinhardInputMax = 1e30;

vec3 acesFit(vec3 x) {
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    x = clamp(x, vec3(0.0), vec3(kAcesInputMax));
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), vec3(0.0), vec3(1.0));
}

vec3 reinhardPerChannel(vec3 x) {
    x = clamp(x, vec3(0.0), vec3(kReinhardInputMax));
    return x / (1.0 + x);
}

// Reinhard 2002, Eq. 3 on luminance: rgb * L_d / L = rgb / (1 + L), clipped to 1.
vec3 reinhardLuminance(vec3 x) {
    x = clamp(x, vec3(0.0), vec3(kReinhardInputMax));
    return min(x / (1.0 + rec709Luminance(x)), vec3(1.0));
}

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(display))) {
        return;
    }
    vec3 x = texelFetch(radiance, p, 0).rgb * params.exposure;
    vec3 y;
    if (params.op == 1u) {
        y = reinhardLuminance(x);
    } else if (params.op == 2u) {
        y = reinhardPerChannel(x);
    } else {
        y = acesFit(x);
    }
    imageStore(display, p, vec4(y, 1.0));
}
