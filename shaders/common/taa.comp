#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Temporal anti-aliasing (Karis 2014, "High Quality Temporal Supersampling"): reproject
// last frame's output through the motion vectors, rectify it against a YCoCg box of
// the current 3x3 neighbourhood, blend with the current colour. The steps, settings
// and their sources: passes/common/taa.hpp.
#include "common/grid.glsl"
#include "common/color_spaces.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D current;
layout(set = 0, binding = 1) uniform texture2D motion;
layout(set = 0, binding = 2) uniform texture2D history;
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D resolved;

layout(push_constant) uniform Params {
    float alpha;           // weight of the current frame
    float varianceGamma;   // box half-size in standard deviations (box == 1)
    uint box;              // TaaBox: 0 min/max, 1 mean +- gamma * stddev
    uint rectify;          // TaaRectify: 0 clamp, 1 clip towards the box centre
    uint historyValid;     // 0 on the first frame and after a reset
} params;

// The smallest normal fp32: the variance box divides by at least this, so a
// denormal spread (flushed or not) cannot make an Inf.
const float kMinNormal = 1.1754944e-38;

vec3 currentAt(ivec2 q, ivec2 size) {
    return texelFetch(current, clamp(q, ivec2(0), size - 1), 0).rgb;
}

vec3 historyAt(ivec2 q, ivec2 size) {
    return texelFetch(history, clamp(q, ivec2(0), size - 1), 0).rgb;
}

// Bilinear history at this pixel's previous position, centre p + 0.5 + m (texel
// centres at +0.5, edge texels repeated); false when that position is off screen.
// Worked in p + m rather than p + 0.5 + m - 0.5: floor(p + m) = p + floor(m) and the
// weights are m - floor(m), both exact in fp32, so the weights do not lose bits as
// the pixel coordinate grows (at x = 256 an fp32 position has 3e-5 px steps).
bool reprojectHistory(ivec2 p, vec2 m, ivec2 size, out vec3 colour) {
    colour = vec3(0.0);
    // 0 <= p + 0.5 + m < size, exact for sizes below 2^22. False for NaN motion, and
    // checked before ivec2(floor(m)), which would be undefined for a huge m.
    vec2 centre = vec2(p) + 0.5;
    if (!all(greaterThanEqual(m, -centre)) || !all(lessThan(m, vec2(size) - centre))) {
        return false;
    }
    vec2 whole = floor(m);
    vec2 f = m - whole;
    ivec2 i = p + ivec2(whole);
    vec3 top = mix(historyAt(i, size), historyAt(i + ivec2(1, 0), size), f.x);
    vec3 bottom = mix(historyAt(i + ivec2(0, 1), size), historyAt(i + ivec2(1, 1), size), f.x);
    colour = mix(top, bottom, f.y);
    return true;
}

struct Box {
    vec3 lo, hi, centre;   // lo <= centre <= hi, YCoCg
};

Box neighbourhoodBox(ivec2 p, ivec2 size) {
    vec3 s[9];
    for (int k = 0; k < 9; ++k) {
        s[k] = rgbToYCoCg(currentAt(p + ivec2(k % 3 - 1, k / 3 - 1), size));
    }
    if (params.box == 1u) {
        // Variance clipping (Salvi 2016): mean +- gamma * stddev. The deviations are
        // divided by the largest one before squaring, so squares neither overflow
        // (1e6^2 is fine, but not 1e20^2) nor underflow (1e-30^2 would be 0 in fp32).
        vec3 mean = vec3(0.0);
        for (int k = 0; k < 9; ++k) {
            mean += s[k];
        }
        mean /= 9.0;
        vec3 spread = vec3(0.0);
        for (int k = 0; k < 9; ++k) {
            spread = max(spread, abs(s[k] - mean));
        }
        vec3 scale = max(spread, vec3(kMinNormal));
        vec3 sumSquares = vec3(0.0);
        for (int k = 0; k < 9; ++k) {
            vec3 d = (s[k] - mean) / scale;
            sumSquares += d * d;
        }
        vec3 halfSize = max(params.varianceGamma, 0.0) * scale * sqrt(sumSquares / 9.0);
        return Box(mean - halfSize, mean + halfSize, mean);
    }
    vec3 lo = s[0], hi = s[0];
    for (int k = 1; k < 9; ++k) {
        lo = min(lo, s[k]);
        hi = max(hi, s[k]);
    }
    // Halves first: (lo + hi) could overflow where lo / 2 + hi / 2 cannot.
    return Box(lo, hi, 0.5 * lo + 0.5 * hi);
}

// The point where the segment from the box centre to h leaves the box (h itself when
// inside). Each quotient has |numerator| < |denominator|, both of one sign, so it
// lies in [0, 1); a denominator flushed to 0 skips that axis instead of dividing.
vec3 clipToBox(vec3 h, Box b) {
    vec3 v = h - b.centre;
    float t = 1.0;
    for (int c = 0; c < 3; ++c) {
        if (h[c] > b.hi[c] && v[c] > 0.0) {
            t = min(t, (b.hi[c] - b.centre[c]) / v[c]);
        } else if (h[c] < b.lo[c] && v[c] < 0.0) {
            t = min(t, (b.lo[c] - b.centre[c]) / v[c]);
        }
    }
    return b.centre + v * t;
}

void main() {
    ivec2 p = hushPixel();
    ivec2 size = imageSize(resolved);
    if (!hushInside(p, size)) {
        return;
    }
    vec3 cur = texelFetch(current, p, 0).rgb;
    vec3 hist;
    bool haveHistory = params.historyValid != 0u &&
                       reprojectHistory(p, texelFetch(motion, p, 0).rg, size, hist);
    vec3 result = cur;
    if (haveHistory) {
        Box b = neighbourhoodBox(p, size);
        vec3 h = rgbToYCoCg(hist);
        h = params.rectify == 1u ? clipToBox(h, b) : clamp(h, b.lo, b.hi);
        // A point of the YCoCg box need not be a colour with non-negative RGB.
        result = max(mix(yCoCgToRgb(h), cur, clamp(params.alpha, 0.0, 1.0)), vec3(0.0));
    }
    imageStore(resolved, p, vec4(result, 1.0));
}
