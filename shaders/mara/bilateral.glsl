// Mara et al. 2017's cross-bilateral tap weight (seed 000 Sec. 3.4: "all bilateral
// filters also read the G-buffer to weight taps by the camera-space plane distance
// in normals and depth from the center sample"):
//   w_plane  = exp(-(|n_c . (X_q - X_c)| / (planeSigma * z_c))^2)   distance of the tap
//              from the centre's tangent plane, relative to the centre's depth so that
//              one sigma serves scenes in millimetres and in metres
//   w_normal = max(0, n_c . n_q)^normalPower
// The including shader declares `normal_depth` (normal xyz, linear depth) and
// `position` (world xyz) as texture2D.
#ifndef HUSH_MARA_BILATERAL_GLSL
#define HUSH_MARA_BILATERAL_GLSL

#include "common/normal_power.glsl"

struct MaraCentre {
    vec3 normal;
    float depth;
    vec3 position;
};

bool maraHasSurface(vec4 normalDepth) {
    return dot(normalDepth.xyz, normalDepth.xyz) > 1e-6;
}

MaraCentre maraCentre(ivec2 p) {
    vec4 nd = texelFetch(normal_depth, p, 0);
    return MaraCentre(nd.xyz, nd.w, texelFetch(position, p, 0).xyz);
}

// 0 for a tap without a surface.
// wholeExponent: wholeExponent(normalPower) on the host (common/normal_power.glsl).
float maraGeometryWeight(MaraCentre c, ivec2 q, float planeSigma, float exponent, uint wholeExponent) {
    vec4 nd = texelFetch(normal_depth, q, 0);
    if (!maraHasSurface(nd)) {
        return 0.0;
    }
    float plane = abs(dot(c.normal, texelFetch(position, q, 0).xyz - c.position)) /
                  max(planeSigma * c.depth, 1e-30);
    float facing = max(dot(c.normal, nd.xyz), 0.0);
    return exp(-min(plane * plane, 80.0)) * normalPower(facing, exponent, wholeExponent);
}

#endif
