#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// SSIM map (passes/metrics/ssim.hpp; Wang, Bovik, Sheikh, Simoncelli 2004, Eq. 13
// with the 11x11 circular-symmetric Gaussian window of Sec. III-C, sigma 1.5,
// normalised). One invocation per window position p (the window's centre pixel):
//   mu_a    = sum_q w(q) a(q)                     (Eq. 14)
//   var_a   = sum_q w(q) (a(q) - mu_a)^2          (Eq. 15)
//   cov_ab  = sum_q w(q) (a(q) - mu_a)(b(q) - mu_b)   (Eq. 16)
//   SSIM    = (2 mu_a mu_b + C1)(2 cov_ab + C2) / ((mu_a^2 + mu_b^2 + C1)(var_a + var_b + C2))
// per RGB channel, then averaged over the three channels. The (co)variances are
// taken about the window mean (two passes over the window) rather than as
// E[a^2] - mu^2, which cancels catastrophically in fp32 for large values.
//
// Positions: along an axis of n >= 11 pixels only those whose window lies inside
// the image ("valid", as Wang's ssim_index.m), centres 5 .. n - 6; along an axis of
// n < 11 pixels every pixel is a centre and the window is clipped to the image and
// renormalised (its taps outside get weight 0; the rest are divided by their sum).
// Output texel: (SSIM, 1, 0, 0) for a counted position; (0, 0, 1, 0) for a position
// whose window holds a non-finite value (excluded, counted); (0, 0, 0, 0) elsewhere.
#include "common/grid.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = 0) uniform texture2D image;
layout(set = 0, binding = 1) uniform texture2D reference;
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D map;

layout(push_constant) uniform Params {
    float c1;      // (K1 L)^2
    float c2;      // (K2 L)^2
    float sigma;   // the Gaussian window's standard deviation, pixels
} params;

const int kRadius = 5;                     // 11 x 11 window
const int kTaps = 2 * kRadius + 1;
const int kGroup = 16;
const int kTile = kGroup + 2 * kRadius;    // the workgroup's pixels and the windows' apron
const int kTileTexels = kTile * kTile;

// The apron tile of both images (texels outside the image hold 0; their weight is 0).
shared vec3 tileImage[kTileTexels];
shared vec3 tileReference[kTileTexels];

// The first and last window centre along an axis of n pixels.
ivec2 centreRange(int n) {
    return n >= kTaps ? ivec2(kRadius, n - 1 - kRadius) : ivec2(0, n - 1);
}

bool allFinite(vec3 v) {
    return !any(isnan(v)) && !any(isinf(v));
}

void main() {
    const ivec2 size = textureSize(image, 0);
    const ivec2 tileOrigin = ivec2(gl_WorkGroupID.xy) * kGroup - kRadius;
    for (uint i = gl_LocalInvocationIndex; i < uint(kTileTexels); i += uint(kGroup * kGroup)) {
        const ivec2 q = tileOrigin + ivec2(int(i) % kTile, int(i) / kTile);
        vec3 a = vec3(0.0), b = vec3(0.0);
        if (hushInside(q, size)) {
            a = texelFetch(image, q, 0).rgb;
            b = texelFetch(reference, q, 0).rgb;
        }
        tileImage[i] = a;
        tileReference[i] = b;
    }
    barrier();

    const ivec2 p = hushPixel();
    if (!hushInside(p, size)) {
        return;
    }
    const ivec2 xRange = centreRange(size.x), yRange = centreRange(size.y);
    if (p.x < xRange.x || p.x > xRange.y || p.y < yRange.x || p.y > yRange.y) {
        imageStore(map, p, vec4(0.0));
        return;
    }

    // Separable weights, each axis normalised over its taps inside the image (all 11
    // for a valid position, so the window is the normalised 11 x 11 Gaussian).
    float wx[kTaps], wy[kTaps];
    float sumX = 0.0, sumY = 0.0;
    for (int k = 0; k < kTaps; ++k) {
        const float g = exp(-float((k - kRadius) * (k - kRadius)) / (2.0 * params.sigma * params.sigma));
        const int qx = p.x + k - kRadius, qy = p.y + k - kRadius;
        wx[k] = (qx >= 0 && qx < size.x) ? g : 0.0;
        wy[k] = (qy >= 0 && qy < size.y) ? g : 0.0;
        sumX += wx[k];
        sumY += wy[k];
    }
    // sumX, sumY >= 1: the centre tap's weight is exp(0) and the centre is inside.
    for (int k = 0; k < kTaps; ++k) {
        wx[k] /= sumX;
        wy[k] /= sumY;
    }

    const ivec2 local = ivec2(gl_LocalInvocationID.xy);   // the centre's tile position is local + kRadius
    vec3 muA = vec3(0.0), muB = vec3(0.0);
    bool finite = true;
    for (int ky = 0; ky < kTaps; ++ky) {
        for (int kx = 0; kx < kTaps; ++kx) {
            const int t = (local.y + ky) * kTile + local.x + kx;
            const float w = wx[kx] * wy[ky];
            const vec3 a = tileImage[t], b = tileReference[t];
            finite = finite && allFinite(a) && allFinite(b);
            muA += w * a;
            muB += w * b;
        }
    }
    if (!finite) {
        imageStore(map, p, vec4(0.0, 0.0, 1.0, 0.0));
        return;
    }
    vec3 varA = vec3(0.0), varB = vec3(0.0), cov = vec3(0.0);
    for (int ky = 0; ky < kTaps; ++ky) {
        for (int kx = 0; kx < kTaps; ++kx) {
            const int t = (local.y + ky) * kTile + local.x + kx;
            const float w = wx[kx] * wy[ky];
            const vec3 da = tileImage[t] - muA, db = tileReference[t] - muB;
            varA += w * da * da;
            varB += w * db * db;
            cov += w * da * db;
        }
    }
    // Both denominators are >= C1 > 0 and >= C2 > 0 (the variances are sums of
    // non-negative terms), so neither division can fail. Each factor is divided on
    // its own, so a product of two large denominators cannot overflow.
    const vec3 luminance = (2.0 * muA * muB + params.c1) / (muA * muA + muB * muB + params.c1);
    const vec3 contrastStructure = (2.0 * cov + params.c2) / (varA + varB + params.c2);
    const vec3 ssim = luminance * contrastStructure;
    imageStore(map, p, vec4((ssim.r + ssim.g + ssim.b) / 3.0, 1.0, 0.0, 0.0));
}
