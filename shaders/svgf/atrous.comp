#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// One level of SVGF's edge-avoiding a-trous filter (Schied et al. 2017, Sec. 4.3,
// Eq. 1 and the variance propagation below it; weights Sec. 4.4, Eq. 2-5). The
// formulas and every guard are spelled out in passes/include/hush/passes/svgf/atrous.hpp.
#include "common/grid.glsl"
#include "common/normal_power.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D illum_variance;        // rgb illumination, a variance
layout(set = 0, binding = 1) uniform texture2D prefiltered_variance;  // g3x3(variance), r
layout(set = 0, binding = 2) uniform texture2D normal_depth;          // normal xyz, linear depth
layout(set = 0, binding = 3) uniform texture2D gradient_mesh;         // dz/dx, dz/dy, mesh id
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D filtered;

layout(push_constant) uniform Params {
    int step;                 // 2^level, capped so that offsets stay in int range
    float sigmaZ;
    float sigmaN;
    float sigmaL;
    float depthEpsilon;       // relative to |z(p)|
    float luminanceEpsilon;
} params;

// sigmaN if it is a whole number, else 0 (common/normal_power.glsl).
layout(constant_id = 0) const uint wholeSigmaN = 0u;

// B3-spline a-trous kernel (1/16, 1/4, 3/8, 1/4, 1/16), indexed by |offset|.
const float kKernel[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
const vec3 kRec709 = vec3(0.2126, 0.7152, 0.0722);
const float kMaxFloat = 3.402823466e38;
const float kMinDepthEpsilon = 1e-20;

// The surface pass zeroes the normal where there is no surface (mesh id < 0 too), so
// a tap's test reads one texture, not two.
bool hasSurface(vec4 nd) {
    return dot(nd.xyz, nd.xyz) > 1e-6;
}

void main() {
    ivec2 p = hushPixel();
    ivec2 size = imageSize(filtered);
    if (!hushInside(p, size)) {
        return;
    }
    vec4 centre = texelFetch(illum_variance, p, 0);
    vec4 ndP = texelFetch(normal_depth, p, 0);
    vec4 gmP = texelFetch(gradient_mesh, p, 0);
    if (!hasSurface(ndP)) {
        // Background: nothing to stop edges with, so it is left as it is.
        imageStore(filtered, p, vec4(centre.rgb, max(centre.a, 0.0)));
        return;
    }
    float lumP = dot(centre.rgb, kRec709);
    // Eq. 5's denominator, > 0 by luminanceEpsilon.
    float lumScale = params.sigmaL * sqrt(max(texelFetch(prefiltered_variance, p, 0).r, 0.0)) +
                     params.luminanceEpsilon;
    float depthEps = max(params.depthEpsilon * abs(ndP.w), kMinDepthEpsilon);

    vec3 colourSum = vec3(0.0);
    float weightSum = 0.0;
    float varianceSum = 0.0;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 offset = ivec2(dx, dy) * params.step;
            ivec2 q = p + offset;
            if (!hushInside(q, size)) {
                continue;
            }
            vec4 c = texelFetch(illum_variance, q, 0);
            float w = 1.0;
            if (dx != 0 || dy != 0) {
                vec4 ndQ = texelFetch(normal_depth, q, 0);
                if (!hasSurface(ndQ)) {
                    continue;
                }
                // Eq. 3: deviation from the centre's depth plane, in units of its slope.
                float wz = exp(-abs(ndP.w - ndQ.w) /
                               (params.sigmaZ * abs(dot(gmP.xy, vec2(offset))) + depthEps));
                // Eq. 4; pow(0, y) is avoided (undefined in GLSL for y <= 0).
                float cosine = min(dot(ndP.xyz, ndQ.xyz), 1.0);
                float wn = cosine > 0.0 ? normalPower(cosine, params.sigmaN, wholeSigmaN) : 0.0;
                // Eq. 5.
                float wl = exp(-abs(lumP - dot(c.rgb, kRec709)) / lumScale);
                w = wz * wn * wl;
            }
            float hw = kKernel[abs(dx)] * kKernel[abs(dy)] * w;
            colourSum += hw * c.rgb;
            weightSum += hw;
            varianceSum += hw * hw * max(c.a, 0.0);
        }
    }
    // weightSum >= (3/8)^2 from the centre tap.
    imageStore(filtered, p,
               vec4(colourSum / weightSum, min(varianceSum / (weightSum * weightSum), kMaxFloat)));
}
