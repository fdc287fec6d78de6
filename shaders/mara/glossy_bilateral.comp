#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Mara et al. 2017 stages 9 and 10, the glossy cross-bilateral blur, separated into a
// horizontal and a vertical pass (seed 000 Sec. 3.4): a Gaussian of standard deviation
//   sigma = sigmaScale * roughness^roughnessExponent + sigmaEpsilon   (pixels; 7, 0.1)
// from the centre's roughness (GGX alpha), over |offset| <= ceil(3 sigma), times the
// plane and normal weights (shaders/mara/bilateral.glsl).
#include "common/grid.glsl"

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
    ivec2 p = hushPixel();
    ivec2 size = imageSize(filtered);
    if (!hushInside(p, size)) {
        return;
    }
    vec4 centre = texelFetch(color, p, 0);
    vec4 nd = texelFetch(normal_depth, p, 0);
    if (!maraHasSurface(nd)) {
        imageStore(filtered, p, centre);
        return;
    }
    MaraCentre c = maraCentre(p);
    float alpha = max(texelFetch(roughness, p, 0).x, 0.0);
    float sigma = params.sigmaScale * pow(alpha, params.roughnessExponent) + params.sigmaEpsilon;
    int r = min(int(ceil(3.0 * sigma)), kMaxRadius);
    ivec2 axis = params.vertical != 0u ? ivec2(0, 1) : ivec2(1, 0);
    float inverseTwoSigma2 = 0.5 / max(sigma * sigma, 1e-30);
    vec3 sum = centre.rgb;
    float weightSum = 1.0;
    for (int k = -r; k <= r; ++k) {
        ivec2 q = p + k * axis;
        if (k == 0 || !hushInside(q, size)) {
            continue;
        }
        float w = exp(-float(k * k) * inverseTwoSigma2) *
                  maraGeometryWeight(c, q, params.planeSigma, params.normalPower, wholeNormalPower);
        sum += w * texelFetch(color, q, 0).rgb;
        weightSum += w;
    }
    imageStore(filtered, p, vec4(sum / weightSum, centre.a));
}
