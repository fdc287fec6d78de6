#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// One level of the edge-avoiding a-trous wavelet filter of Dammertz et al. 2010
// (HPG 2010): B3-spline 5x5 kernel at step 2^level, weights
// exp(-||I(p) - I(q)||^2 / sigma^2) on colour, normal and world position, multiplied.
// Formulas and guards: passes/include/hush/passes/eaw/atrous.hpp.
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D color;      // rgb filtered, a copied
layout(set = 0, binding = 1) uniform texture2D normal;     // xyz, 0 where no surface
layout(set = 0, binding = 2) uniform texture2D position;   // world xyz
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D filtered;
layout(set = 0, binding = 4) uniform texture2D depth;      // linear depth (read when depthRelative)

layout(push_constant) uniform Params {
    int step;          // 2^level, capped so that offsets stay in int range
    float sigmaRt2;    // (2^-level sigma_rt)^2, >= 1e-30; relative to the local mean luminance squared when colorRelative
    float sigmaN2;     // >= 1e-30
    float sigmaX2;     // >= 1e-30
    uint depthRelative;   // 1: position distances are divided by the centre's depth
    uint colorRelative;   // 1: colour distances are divided by the local mean luminance
} params;

const float kKernel[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);

bool hasSurface(vec3 n) {
    return dot(n, n) > 1e-6;
}

float luminance(vec3 c) {
    return abs(dot(c, vec3(0.2126, 0.7152, 0.0722)));
}

float squaredDistance(vec3 a, vec3 b) {
    vec3 d = a - b;
    return dot(d, d);
}

void main() {
    ivec2 p = hushPixel();
    ivec2 size = imageSize(filtered);
    if (!hushInside(p, size)) {
        return;
    }
    vec4 centre = texelFetch(color, p, 0);
    vec3 nP = texelFetch(normal, p, 0).xyz;
    if (!hasSurface(nP)) {
        imageStore(filtered, p, centre);
        return;
    }
    vec3 xP = texelFetch(position, p, 0).xyz;
    // Scale-free position weight: ||x_p - x_q|| / z_p, so that one sigma suits a scene
    // modelled in millimetres and one in metres (docs/passes/eaw.md).
    float xScale2 = 1.0;
    if (params.depthRelative != 0u) {
        float z = max(abs(texelFetch(depth, p, 0).x), 1e-20);
        xScale2 = z * z;
    }
    // The 5x5 taps' colours and normals, read once: the scale-free colour weight needs
    // their mean luminance before any weight (docs/passes/eaw.md).
    vec3 tapColour[25];
    vec3 tapNormal[25];
    bool tapUsed[25];
    float luminanceSum = 0.0, kernelSum = 0.0;
    for (int t = 0; t < 25; ++t) {
        ivec2 q = p + ivec2(t % 5 - 2, t / 5 - 2) * params.step;
        tapUsed[t] = false;
        if (!hushInside(q, size)) {
            continue;
        }
        tapColour[t] = texelFetch(color, q, 0).rgb;
        tapNormal[t] = texelFetch(normal, q, 0).xyz;
        if (t != 12 && !hasSurface(tapNormal[t])) {
            continue;
        }
        tapUsed[t] = true;
        float h = kKernel[abs(t % 5 - 2)] * kKernel[abs(t / 5 - 2)];
        luminanceSum += h * luminance(tapColour[t]);
        kernelSum += h;
    }
    // Scale-free: distances over the local mean luminance (floored at 1e-20), as the
    // position weight is over depth; a frame 1000x brighter is filtered alike.
    float sigmaRt2 = params.sigmaRt2;
    if (params.colorRelative != 0u) {
        float l = max(luminanceSum / kernelSum, 1e-20);
        sigmaRt2 = max(sigmaRt2 * l * l, 1e-30);
    }

    vec3 colourSum = vec3(0.0);
    float weightSum = 0.0;
    for (int t = 0; t < 25; ++t) {
        if (!tapUsed[t]) {
            continue;
        }
        vec3 c = tapColour[t];
        float w = 1.0;
        if (t != 12) {
            ivec2 q = p + ivec2(t % 5 - 2, t / 5 - 2) * params.step;
            vec3 xQ = texelFetch(position, q, 0).xyz;
            // w_rt w_n w_x as one exponential of the summed exponents.
            w = exp(-(squaredDistance(centre.rgb, c) / sigmaRt2 + squaredDistance(nP, tapNormal[t]) / params.sigmaN2 +
                      squaredDistance(xP, xQ) / (params.sigmaX2 * xScale2)));
        }
        float hw = kKernel[abs(t % 5 - 2)] * kKernel[abs(t / 5 - 2)] * w;
        colourSum += hw * c;
        weightSum += hw;
    }
    // weightSum >= (3/8)^2 from the centre tap.
    imageStore(filtered, p, vec4(colourSum / weightSum, centre.a));
}
