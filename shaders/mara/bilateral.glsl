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
    vec3 position;
    float inversePlaneScale;   // 1 / (planeSigma * z_c)
};

bool maraHasSurface(vec4 normalDepth) {
    return dot(normalDepth.xyz, normalDepth.xyz) > 1e-6;
}

MaraCentre maraCentre(ivec2 p, float planeSigma) {
    vec4 nd = texelFetch(normal_depth, p, 0);
    return MaraCentre(nd.xyz, texelFetch(position, p, 0).xyz, 1.0 / max(planeSigma * nd.w, 1e-30));
}

// The weight of a tap with normal_depth `nd` and world position `x`: exp(-gaussianExponent)
// (the caller's spatial Gaussian, folded into the plane weight's exp()) * w_plane *
// w_normal; 0 for a tap without a surface. Without a branch: on lavapipe a tap that
// branches costs about twice one that is computed and then weighed 0
// (docs/benchmarks.md, issue 14).
// wholeExponent: wholeExponent(normalPower) on the host (common/normal_power.glsl).
float maraTapWeight(MaraCentre c, vec4 nd, vec3 x, float gaussianExponent, float exponent, uint wholeExponent) {
    float plane = abs(dot(c.normal, x - c.position)) * c.inversePlaneScale;
    float facing = max(dot(c.normal, nd.xyz), 0.0);
    float w = exp(-(gaussianExponent + min(plane * plane, 80.0))) * normalPower(facing, exponent, wholeExponent);
    return maraHasSurface(nd) ? w : 0.0;
}

#endif
