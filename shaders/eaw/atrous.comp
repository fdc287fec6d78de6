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
    float sigmaRt2;    // (2^-level sigma_rt)^2, >= 1e-30
    float sigmaN2;     // >= 1e-30
    float sigmaX2;     // >= 1e-30
    uint depthRelative;   // 1: position distances are divided by the centre's depth
} params;

const float kKernel[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);

bool hasSurface(vec3 n) {
    return dot(n, n) > 1e-6;
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

    vec3 colourSum = vec3(0.0);
    float weightSum = 0.0;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 q = p + ivec2(dx, dy) * params.step;
            if (!hushInside(q, size)) {
                continue;
            }
            vec3 c = texelFetch(color, q, 0).rgb;
            float w = 1.0;
            if (dx != 0 || dy != 0) {
                vec3 nQ = texelFetch(normal, q, 0).xyz;
                if (!hasSurface(nQ)) {
                    continue;
                }
                vec3 xQ = texelFetch(position, q, 0).xyz;
                // w_rt w_n w_x as one exponential of the summed exponents.
                w = exp(-(squaredDistance(centre.rgb, c) / params.sigmaRt2 +
                          squaredDistance(nP, nQ) / params.sigmaN2 +
                          squaredDistance(xP, xQ) / (params.sigmaX2 * xScale2)));
            }
            float hw = kKernel[abs(dx)] * kKernel[abs(dy)] * w;
            colourSum += hw * c;
            weightSum += hw;
        }
    }
    // weightSum >= (3/8)^2 from the centre tap.
    imageStore(filtered, p, vec4(colourSum / weightSum, centre.a));
}
