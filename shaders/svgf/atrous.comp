#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
// One level of SVGF's edge-avoiding a-trous filter (Schied et al. 2017, Sec. 4.3,
// Eq. 1 and the variance propagation below it; weights Sec. 4.4, Eq. 2-5). The
// formulas and every guard are spelled out in passes/include/hush/passes/svgf/atrous.hpp.
#include "common/grid.glsl"
#include "common/normal_power.glsl"

// One invocation filters a kBlock x kBlock block of pixels `step` apart (the a-trous
// lattice, docs/passes/atrous-lattice.md): their 5x5 windows overlap, so each tap
// texel is fetched once for the block ((kBlock + 4)^2 fetches per resource for
// kBlock^2 pixels instead of 25 each) and used at once by every pixel whose window
// holds it, without being kept. The host dispatches atrousThreads(size, step, kBlock)
// (svgf/atrous.cpp: kAtrousBlock). Every tap is evaluated without a branch: one off
// the image or without a surface is fetched clamped and weighs exactly 0. With
// `continue` there instead, as in the one-pixel shader, the lattice was 2x slower
// than one pixel per invocation. Each pixel adds its taps in the one-pixel loop's
// order (rows, then columns), and a skipped tap adds +0.
const int kBlock = 4;
const int kBlockPixels = kBlock * kBlock;

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

// The block's first pixel: per axis, invocation i is residue i % step of cell
// i / step, whose kBlock pixels span kBlock * step pixels.
ivec2 blockStart(int step) {
    ivec2 i = ivec2(gl_GlobalInvocationID.xy);
    ivec2 cell = i / step;
    return cell * kBlock * step + (i - cell * step);
}

// Pixel k of the block (row-major), in steps from its first pixel.
ivec2 blockOffset(int k) {
    return ivec2(k % kBlock, k / kBlock);
}

void main() {
    ivec2 size = imageSize(filtered);
    int step = params.step;
    ivec2 first = blockStart(step);
    if (!hushInside(first, size)) {
        return;
    }
    // Per pixel of the block: its centre terms and its sums.
    vec4 ndP[kBlockPixels];
    vec2 gradient[kBlockPixels];
    float lumP[kBlockPixels];
    float inverseLumScale[kBlockPixels];
    float depthEps[kBlockPixels];
    bool filtering[kBlockPixels];
    vec3 colourSum[kBlockPixels];
    float weightSum[kBlockPixels];
    float varianceSum[kBlockPixels];
    [[unroll]] for (int k = 0; k < kBlockPixels; ++k) {
        ivec2 p = first + blockOffset(k) * step;
        bool inside = hushInside(p, size);
        ivec2 pc = min(p, size - 1);
        ndP[k] = texelFetch(normal_depth, pc, 0);
        filtering[k] = inside && hasSurface(ndP[k]);
        gradient[k] = texelFetch(gradient_mesh, pc, 0).xy;
        lumP[k] = dot(texelFetch(illum_variance, pc, 0).rgb, kRec709);
        // Eq. 5's denominator, > 0 by luminanceEpsilon.
        inverseLumScale[k] = 1.0 / (params.sigmaL * sqrt(max(texelFetch(prefiltered_variance, pc, 0).r, 0.0)) +
                                    params.luminanceEpsilon);
        depthEps[k] = max(params.depthEpsilon * abs(ndP[k].w), kMinDepthEpsilon);
        colourSum[k] = vec3(0.0);
        weightSum[k] = 0.0;
        varianceSum[k] = 0.0;
    }
    [[unroll]] for (int row = 0; row < kBlock + 4; ++row) {
        [[unroll]] for (int column = 0; column < kBlock + 4; ++column) {
            ivec2 q = first + ivec2(column - 2, row - 2) * step;
            bool insideQ = hushInside(q, size);
            ivec2 qc = clamp(q, ivec2(0), size - 1);
            vec4 c = texelFetch(illum_variance, qc, 0);
            vec4 ndQ = texelFetch(normal_depth, qc, 0);
            bool surfaceQ = insideQ && hasSurface(ndQ);
            float lumQ = dot(c.rgb, kRec709);
            [[unroll]] for (int k = 0; k < kBlockPixels; ++k) {
                int dx = column - 2 - blockOffset(k).x;
                int dy = row - 2 - blockOffset(k).y;
                if (dx < -2 || dx > 2 || dy < -2 || dy > 2) {
                    continue;   // decided at compile time: the loops are unrolled
                }
                float w;
                if (dx == 0 && dy == 0) {
                    w = 1.0;
                } else {
                    vec2 offset = vec2(dx, dy) * float(step);
                    // Eq. 3: deviation from the centre's depth plane, in units of its slope.
                    float ez = abs(ndP[k].w - ndQ.w) /
                               (params.sigmaZ * abs(dot(gradient[k], offset)) + depthEps[k]);
                    // Eq. 4; pow(0, y) is avoided (undefined in GLSL for y <= 0).
                    float cosine = min(dot(ndP[k].xyz, ndQ.xyz), 1.0);
                    float wn = cosine > 0.0 ? normalPower(cosine, params.sigmaN, wholeSigmaN) : 0.0;
                    // Eq. 5; Eq. 3's and Eq. 5's exponentials as one exp(): a tap costs one.
                    float el = abs(lumP[k] - lumQ) * inverseLumScale[k];
                    float wzl = exp(-(ez + el));
                    w = surfaceQ ? wzl * wn : 0.0;
                }
                float hw = kKernel[abs(dx)] * kKernel[abs(dy)] * w;
                colourSum[k] += hw * c.rgb;
                weightSum[k] += hw;
                varianceSum[k] += hw * hw * max(c.a, 0.0);
            }
        }
    }
    [[unroll]] for (int k = 0; k < kBlockPixels; ++k) {
        ivec2 p = first + blockOffset(k) * step;
        if (!hushInside(p, size)) {
            continue;
        }
        // Background: nothing to stop edges with, so it is left as it is. Else
        // weightSum >= (3/8)^2 from the centre tap.
        vec4 centre = texelFetch(illum_variance, p, 0);
        vec4 result = filtering[k] ? vec4(colourSum[k] / weightSum[k],
                                          min(varianceSum[k] / (weightSum[k] * weightSum[k]), kMaxFloat))
                                   : vec4(centre.rgb, max(centre.a, 0.0));
        imageStore(filtered, p, result);
    }
}
