// Temporal anti-aliasing (Karis 2014, "High Quality Temporal Supersampling"): reproject
// last frame's output through the motion vectors (and, if given, a reprojection
// decision), rectify it against a YCoCg box of the current 3x3 neighbourhood, blend
// with the current colour. The steps, settings and their sources:
// passes/common/taa.hpp.
//
// Three variants (docs/passes/common.md, "Tile lists"): common/taa.comp, every pixel
// (without a reprojection decision); common/taa_classify.comp (HUSH_TAA_CLASSIFY),
// every pixel whose decision keeps a whole 2x2 footprint or none, listing the tiles
// where a pixel's footprint is partial; common/taa_partial.comp (HUSH_LISTED_TILES),
// every pixel of those tiles. A partial footprint's nine taps then cost only there.
// Needs GL_EXT_samplerless_texture_functions.
#ifndef HUSH_COMMON_TAA_GLSL
#define HUSH_COMMON_TAA_GLSL
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D color;
layout(set = 0, binding = 1) uniform texture2D motion;
layout(set = 0, binding = 2) uniform texture2D history;
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D resolved;
// common/reproject's decision (reproject.hpp); not read when useReprojection is 0.
layout(set = 0, binding = 4) uniform texture2D reprojection;
#if defined(HUSH_TAA_CLASSIFY) || defined(HUSH_LISTED_TILES)
#define HUSH_TILE_LIST_BINDING 5
#endif
#include "common/tile_list.glsl"
const uvec2 kTile = uvec2(8, 8);   // one workgroup

layout(push_constant) uniform Params {
    float alpha;             // weight of the current frame
    float varianceGamma;     // box half-size in standard deviations (box == 1)
    uint historyValid;       // 0 on the first frame and after a reset
} params;

// The choices as specialization constants, so that the driver compiles only the
// chosen path: as push constants every pixel carried all of them (docs/benchmarks.md).
layout(constant_id = 0) const uint box = 0u;              // TaaBox: 0 min/max, 1 mean +- gamma * stddev
layout(constant_id = 1) const uint rectify = 1u;          // TaaRectify: 0 clamp, 1 clip towards the box centre
layout(constant_id = 2) const uint historyFilter = 1u;    // TaaHistoryFilter: 0 bilinear, 1 Catmull-Rom
layout(constant_id = 3) const uint useReprojection = 0u;  // 1: a reprojection decision is bound

#include "common/color_spaces.glsl"
#include "common/reprojection.glsl"
#include "common/taa_history.glsl"

// The smallest normal fp32: the variance box divides by at least this, so a
// denormal spread (flushed or not) cannot make an Inf.
const float kMinNormal = 1.1754944e-38;
// How far outside the box (relative to its size) a history component must be to be
// clipped: see clipToBox. 2^-16, well above fp32 rounding of the history (about
// 1e-6 relative for Catmull-Rom's 16 taps), far below a display quantum (2^-8).
const float kClipMargin = 1.0 / 65536.0;

vec3 currentAt(ivec2 q, ivec2 size) {
    return texelFetch(color, clamp(q, ivec2(0), size - 1), 0).rgb;
}

// True when the decision's 2x2 footprint kept every tap of positive bilinear weight
// (reproject.hpp: a tap is set only if consistent and of weight > 0): the surface
// is the same all around the previous position, so the history filter may be used.
bool wholeFootprint(vec4 decision) {
    vec2 frac = decision.xy - floor(decision.xy);
    uint positive = 1u | (frac.x > 0.0 ? 2u : 0u) | (frac.y > 0.0 ? 4u : 0u) |
                    (frac.x > 0.0 && frac.y > 0.0 ? 8u : 0u);
    return uint(decision.w + 0.5) == kReprojectBilinear && uint(decision.z + 0.5) == positive;
}

// Last frame's output at this pixel's previous position; false where there is none.
// `deferred`: the pixel is left to the listed variant (a partial footprint).
// With a reprojection decision: none where it says disoccluded; the history filter
// where the whole 2x2 footprint holds this surface; else the decision's own
// renormalised footprint (SVGF Sec. 4.1), which leaves out the other surfaces' taps.
bool historyAt(ivec2 p, ivec2 size, out vec3 colour, out bool deferred) {
    colour = vec3(0.0);
    deferred = false;
    vec2 m = texelFetch(motion, p, 0).rg;
    if (useReprojection != 0u) {
        vec4 decision = texelFetch(reprojection, p, 0);
        ReprojectionFootprint footprint;
        if (!reprojectionFootprint(decision, footprint)) {
            return false;
        }
        if (!wholeFootprint(decision)) {
#ifdef HUSH_TAA_CLASSIFY
            hushListTile(size, kTile);
            deferred = true;
            return false;
#else
            colour = fetchFootprint(history, footprint).rgb;
            return true;
#endif
        }
    }
    return resampleTaaHistory(p, m, size, historyFilter, colour);
}

struct Box {
    vec3 lo, hi, centre;   // lo <= centre <= hi, YCoCg
};

Box neighbourhoodBox(ivec2 p, ivec2 size) {
    vec3 s[9];
    for (int k = 0; k < 9; ++k) {
        s[k] = rgbToYCoCg(currentAt(p + ivec2(k % 3 - 1, k / 3 - 1), size));
    }
    if (box == 1u) {
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
// inside). A component counts as outside only beyond a margin of 2^-16 of the box's
// largest |component|: where the box is flat along an axis (two colours of equal
// luma, say), fp32 rounding puts a history that lies on that face a hair outside,
// and the quotient of two rounding errors would then move it anywhere between the
// face and the centre (found with a Catmull-Rom history at an edge between two
// colours of equal Y). Each quotient has |numerator| < |denominator|, both of one
// sign, so it lies in [0, 1), and the denominator exceeds the margin.
vec3 clipToBox(vec3 h, Box b) {
    vec3 v = h - b.centre;
    vec3 extent = max(abs(b.lo), abs(b.hi));
    float margin = max(extent.x, max(extent.y, extent.z)) * kClipMargin;
    float t = 1.0;
    for (int c = 0; c < 3; ++c) {
        if (h[c] > b.hi[c] + margin && v[c] > 0.0) {
            t = min(t, (b.hi[c] - b.centre[c]) / v[c]);
        } else if (h[c] < b.lo[c] - margin && v[c] < 0.0) {
            t = min(t, (b.lo[c] - b.centre[c]) / v[c]);
        }
    }
    return b.centre + v * t;
}

void main() {
    ivec2 size = imageSize(resolved);
    ivec2 p = hushTilePixel(size, kTile);
    if (!hushInside(p, size)) {
        return;
    }
    vec3 cur = texelFetch(color, p, 0).rgb;
    vec3 hist;
    bool deferred = false;
    bool haveHistory = params.historyValid != 0u && historyAt(p, size, hist, deferred);
    if (deferred) {
        return;
    }
    vec3 result = cur;
    if (haveHistory) {
        Box b = neighbourhoodBox(p, size);
        vec3 h = rgbToYCoCg(hist);
        h = rectify == 1u ? clipToBox(h, b) : clamp(h, b.lo, b.hi);
        // A point of the YCoCg box need not be a colour with non-negative RGB (nor
        // need a Catmull-Rom value: its negative lobes overshoot at edges).
        result = max(mix(yCoCgToRgb(h), cur, clamp(params.alpha, 0.0, 1.0)), vec3(0.0));
    }
    imageStore(resolved, p, vec4(result, 1.0));
}

#endif
