#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// SVGF variance estimation (Schied et al. 2017, Sec. 4.2): temporal variance from the
// integrated luminance moments, or, where the history is short, a bilateral spatial
// estimate of moments and colour with the depth (Eq. 3) and normal (Eq. 4) weights.
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D color;
layout(set = 0, binding = 1) uniform texture2D moments;
layout(set = 0, binding = 2) uniform texture2D normal_depth;
layout(set = 0, binding = 3) uniform texture2D gradient_mesh;
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D illum_variance;

layout(push_constant) uniform Params {
    float minHistoryLength;
    int radius;
    float sigmaZ;
    float sigmaN;
    float depthEpsilon;
    uint shortHistoryBoost;
} params;

// Eq. 3 and 4 without the luminance term. The denominator is kept positive, and
// depths are finite, so the ratio is in [0, inf] and exp() never sees a NaN.
float geometricWeight(vec4 centre, vec2 gradient, vec4 other, ivec2 offset) {
    float scale = params.sigmaZ * abs(dot(gradient, vec2(offset))) + params.depthEpsilon;
    float wz = exp(-abs(centre.w - other.w) / max(scale, 1e-30));
    float wn = pow(max(0.0, dot(centre.xyz, other.xyz)), params.sigmaN);
    return wz * wn;
}

void main() {
    ivec2 p = hushPixel();
    ivec2 size = imageSize(illum_variance);
    if (!hushInside(p, size)) {
        return;
    }
    vec3 c = texelFetch(color, p, 0).rgb;
    vec4 mu = texelFetch(moments, p, 0);
    float n = max(mu.z, 1.0);
    if (n >= params.minHistoryLength) {
        imageStore(illum_variance, p, vec4(c, max(0.0, mu.y - mu.x * mu.x)));
        return;
    }

    vec4 centre = texelFetch(normal_depth, p, 0);
    vec2 gradient = texelFetch(gradient_mesh, p, 0).xy;
    float sumW = 1.0;   // the centre, whatever its normal
    vec3 sumC = c;
    vec2 sumMu = mu.xy;
    for (int dy = -params.radius; dy <= params.radius; ++dy) {
        for (int dx = -params.radius; dx <= params.radius; ++dx) {
            ivec2 q = p + ivec2(dx, dy);
            if ((dx == 0 && dy == 0) || !hushInside(q, size)) {
                continue;
            }
            float w = geometricWeight(centre, gradient, texelFetch(normal_depth, q, 0), ivec2(dx, dy));
            if (w > 0.0) {
                sumW += w;
                sumC += w * texelFetch(color, q, 0).rgb;
                sumMu += w * texelFetch(moments, q, 0).xy;
            }
        }
    }
    vec3 meanC = sumC / sumW;   // sumW >= 1
    vec2 meanMu = sumMu / sumW;
    float variance = max(0.0, meanMu.y - meanMu.x * meanMu.x);
    if (params.shortHistoryBoost != 0u) {
        variance *= params.minHistoryLength / n;
    }
    imageStore(illum_variance, p, vec4(meanC, variance));
}
