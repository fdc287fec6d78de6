// SVGF variance estimation (Schied et al. 2017, Sec. 4.2): temporal variance from the
// integrated luminance moments, or, where the history is short, a bilateral spatial
// estimate of moments and colour with the depth (Eq. 3) and normal (Eq. 4) weights.
//
// One invocation filters a row of kRow horizontally adjacent pixels: their windows
// overlap, so each tap texel is fetched once for all of them ((kRow + 2r)(2r + 1)
// fetches per resource for kRow pixels instead of kRow (2r + 1)^2) and used at once,
// so nothing but the row's sums stays in registers. Every pixel adds its taps in the
// same order as a one-pixel loop would; a tap that does not count for it (off the
// image, its own centre's, outside its window, weight 0) adds +0.
//
// Two variants (common/tile_list.glsl): svgf/variance_estimate.comp writes every
// pixel of long history and lists the tiles where a pixel's history is short;
// svgf/variance_spatial.comp (HUSH_LISTED_TILES) writes every pixel of those tiles.
// So the 7x7 estimate costs only in tiles after a disocclusion, not every frame.
// Needs GL_EXT_samplerless_texture_functions and GL_EXT_control_flow_attributes.
#ifndef HUSH_SVGF_VARIANCE_ESTIMATE_GLSL
#define HUSH_SVGF_VARIANCE_ESTIMATE_GLSL
#include "common/grid.glsl"
#include "common/normal_power.glsl"

// Pixels per invocation along x; the host dispatches ceil(width / kRow) columns
// (kVarianceRow in variance_estimate.cpp).
const int kRow = 4;

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D color;
layout(set = 0, binding = 1) uniform texture2D moments;
layout(set = 0, binding = 2) uniform texture2D normal_depth;
layout(set = 0, binding = 3) uniform texture2D gradient_mesh;
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D illum_variance;
#define HUSH_TILE_LIST_BINDING 5
#include "common/tile_list.glsl"
// One tile is one workgroup: 8 x 8 invocations of kRow pixels each.
const uvec2 kTile = uvec2(8 * kRow, 8);

layout(push_constant) uniform Params {
    float minHistoryLength;
    float sigmaZ;
    float sigmaN;
    float depthEpsilon;
    uint shortHistoryBoost;
} params;

// sigmaN if it is a whole number, else 0 (common/normal_power.glsl).
layout(constant_id = 0) const uint wholeSigmaN = 0u;
// The window's radius (0 .. 16; 3 is the paper's 7x7). A specialization constant, so
// that the driver unrolls the tap loops: every tap is then evaluated without a
// branch (fetched clamped, weighed 0 where it does not count), about 1.5x faster
// than the loops over a push-constant radius (docs/benchmarks.md).
layout(constant_id = 1) const int radius = 3;

// Eq. 3 and 4 without the luminance term. The denominator is kept positive, and
// depths are finite, so the ratio is in [0, inf] and exp() never sees a NaN.
float geometricWeight(vec4 centre, vec2 gradient, vec4 other, ivec2 offset) {
    float scale = params.sigmaZ * abs(dot(gradient, vec2(offset))) + params.depthEpsilon;
    float wz = exp(-abs(centre.w - other.w) / max(scale, 1e-30));
    float wn = normalPower(max(0.0, dot(centre.xyz, other.xyz)), params.sigmaN, wholeSigmaN);
    return wz * wn;
}

// The variance of spatially estimated moments `mu` at history length n.
float shortHistoryVariance(vec2 mu, float n) {
    float variance = max(0.0, mu.y - mu.x * mu.x);
    if (params.shortHistoryBoost != 0u) {
        variance *= params.minHistoryLength / n;
    }
    return variance;
}

void main() {
    ivec2 size = imageSize(illum_variance);
    ivec2 first = hushTilePixel(size, kTile, uvec2(kRow, 1));
    if (!hushInside(first, size)) {
        return;
    }
    // Per pixel of the row: does it need the spatial estimate, its centre, its sums.
    bool spatial[kRow];
    vec4 centre[kRow];
    vec2 gradient[kRow];
    float n[kRow];
    float sumW[kRow];
    vec3 sumC[kRow];
    vec2 sumMu[kRow];
    bool any = false;
    [[unroll]] for (int k = 0; k < kRow; ++k) {
        ivec2 p = first + ivec2(k, 0);
        spatial[k] = false;
        centre[k] = vec4(0.0);
        gradient[k] = vec2(0.0);
        sumW[k] = 1.0;
        sumC[k] = vec3(0.0);
        sumMu[k] = vec2(0.0);
        n[k] = 1.0;
        if (!hushInside(p, size)) {
            continue;
        }
        vec3 c = texelFetch(color, p, 0).rgb;
        vec4 mu = texelFetch(moments, p, 0);
        n[k] = max(mu.z, 1.0);
        if (n[k] >= params.minHistoryLength) {
            imageStore(illum_variance, p, vec4(c, max(0.0, mu.y - mu.x * mu.x)));
            continue;
        }
        vec4 nd = texelFetch(normal_depth, p, 0);
        // No normal (no surface): with sigmaN > 0 no neighbour weighs (w_n = 0), so
        // the estimate is the pixel's own, here, without listing the tile for it.
        if (params.sigmaN > 0.0 && dot(nd.xyz, nd.xyz) == 0.0) {
            imageStore(illum_variance, p, vec4(c, shortHistoryVariance(mu.xy, n[k])));
            continue;
        }
#ifndef HUSH_LISTED_TILES
        hushListTile(size, kTile);   // svgf/variance_spatial.comp estimates it
#endif
        spatial[k] = true;
        any = true;
        centre[k] = nd;
        gradient[k] = texelFetch(gradient_mesh, p, 0).xy;
        sumW[k] = 1.0;   // the centre, whatever its normal
        sumC[k] = c;
        sumMu[k] = mu.xy;
    }
#ifndef HUSH_LISTED_TILES
    return;
#endif
    if (!any) {
        return;
    }
    // `radius` itself, not a local alias: glslang gives an alias of a specialization
    // constant the constant's SPIR-V id, and its name would replace the constant's.
    [[unroll]] for (int dy = -radius; dy <= radius; ++dy) {
        [[unroll]] for (int dx = -radius; dx <= radius + kRow - 1; ++dx) {
            ivec2 q = first + ivec2(dx, dy);
            bool inside = hushInside(q, size);
            ivec2 qc = clamp(q, ivec2(0), size - 1);
            vec4 nd = texelFetch(normal_depth, qc, 0);
            vec3 cq = texelFetch(color, qc, 0).rgb;
            vec2 mq = texelFetch(moments, qc, 0).xy;
            [[unroll]] for (int k = 0; k < kRow; ++k) {
                int ox = dx - k;
                if (ox < -radius || ox > radius || (ox == 0 && dy == 0)) {
                    continue;
                }
                float w = geometricWeight(centre[k], gradient[k], nd, ivec2(ox, dy));
                w = inside && spatial[k] && w > 0.0 ? w : 0.0;
                sumW[k] += w;
                sumC[k] += w * cq;
                sumMu[k] += w * mq;
            }
        }
    }
    [[unroll]] for (int k = 0; k < kRow; ++k) {
        if (!spatial[k]) {
            continue;
        }
        vec3 meanC = sumC[k] / sumW[k];   // sumW >= 1
        vec2 meanMu = sumMu[k] / sumW[k];
        imageStore(illum_variance, first + ivec2(k, 0), vec4(meanC, shortHistoryVariance(meanMu, n[k])));
    }
}

#endif
