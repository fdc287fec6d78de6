#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
// Mara et al. 2017 stages 9 and 10, the glossy cross-bilateral blur, separated into a
// horizontal and a vertical pass (seed 000 Sec. 3.4): a Gaussian of standard deviation
//   sigma = sigmaScale * roughness^roughnessExponent + sigmaEpsilon   (pixels; 7, 0.1)
// from the centre's roughness (GGX alpha), over |offset| <= ceil(3 sigma), times the
// plane and normal weights (shaders/mara/bilateral.glsl).
//
// One invocation filters kRow neighbouring pixels along the blur's axis: their tap
// lines overlap, so each tap texel is fetched once for the row (2 R + kRow fetches per
// resource, R the row's largest radius, instead of kRow (2 r + 1)) and weighed at once
// for every pixel whose line holds it. Every tap is evaluated without a branch (one off
// the image, at the centre or past a pixel's radius weighs exactly 0), and each pixel
// adds its taps in the order of the one-pixel loop. The host dispatches
// ceil(extent / kRow) invocations along the axis (mara/glossy_bilateral.cpp: kGlossyRow).
#include "common/grid.glsl"

const int kRow = 4;

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D color;
layout(set = 0, binding = 1) uniform texture2D roughness;
layout(set = 0, binding = 2) uniform texture2D normal_depth;
layout(set = 0, binding = 3) uniform texture2D position;
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D filtered;

layout(push_constant) uniform Params {
    float sigmaScale;
    float roughnessExponent;
    float sigmaEpsilon;
    float planeSigma;
    float normalPower;
    uint vertical;   // 0: along x, 1: along y
} params;

// normalPower if it is a whole number, else 0 (common/normal_power.glsl).
layout(constant_id = 0) const uint wholeNormalPower = 0u;

#include "mara/bilateral.glsl"

// sigma = 7 + epsilon at roughness 1: 3 sigma stays below this many taps each side.
const int kMaxRadius = 32;

void main() {
    ivec2 size = imageSize(filtered);
    ivec2 axis = params.vertical != 0u ? ivec2(0, 1) : ivec2(1, 0);
    ivec2 i = ivec2(gl_GlobalInvocationID.xy);
    ivec2 first = params.vertical != 0u ? ivec2(i.x, i.y * kRow) : ivec2(i.x * kRow, i.y);
    if (!hushInside(first, size)) {
        return;
    }
    ivec2 last = size - 1;
    // Per pixel of the row: its centre terms, radius (0: left as it is) and sums.
    MaraCentre c[kRow];
    int radius[kRow];
    float inverseTwoSigma2[kRow];
    vec3 sum[kRow];
    float weightSum[kRow];
    int rowRadius = 0;
    [[unroll]] for (int k = 0; k < kRow; ++k) {
        ivec2 p = first + k * axis;
        ivec2 pc = min(p, last);
        c[k] = maraCentre(pc, params.planeSigma);
        float alpha = max(texelFetch(roughness, pc, 0).x, 0.0);
        float sigma = params.sigmaScale * pow(alpha, params.roughnessExponent) + params.sigmaEpsilon;
        bool filtering = hushInside(p, size) && maraHasSurface(texelFetch(normal_depth, pc, 0));
        radius[k] = filtering ? min(int(ceil(3.0 * sigma)), kMaxRadius) : 0;
        inverseTwoSigma2[k] = 0.5 / max(sigma * sigma, 1e-30);
        sum[k] = texelFetch(color, pc, 0).rgb;
        weightSum[k] = 1.0;
        rowRadius = max(rowRadius, radius[k]);
    }
    for (int t = -rowRadius; t < rowRadius + kRow; ++t) {
        ivec2 q = first + t * axis;
        bool insideQ = hushInside(q, size);
        q = clamp(q, ivec2(0), last);
        vec4 ndQ = texelFetch(normal_depth, q, 0);
        vec3 xQ = texelFetch(position, q, 0).xyz;
        vec3 colourQ = texelFetch(color, q, 0).rgb;
        [[unroll]] for (int k = 0; k < kRow; ++k) {
            int offset = t - k;
            bool counts = insideQ && offset != 0 && abs(offset) <= radius[k];
            float w = maraTapWeight(c[k], ndQ, xQ, float(offset * offset) * inverseTwoSigma2[k], params.normalPower,
                                    wholeNormalPower);
            w = counts ? w : 0.0;
            sum[k] += w * colourQ;
            weightSum[k] += w;
        }
    }
    [[unroll]] for (int k = 0; k < kRow; ++k) {
        ivec2 p = first + k * axis;
        if (hushInside(p, size)) {
            float alpha = texelFetch(color, p, 0).a;
            imageStore(filtered, p, vec4(sum[k] / weightSum[k], alpha));
        }
    }
}
