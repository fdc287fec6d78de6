#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
// One level of the edge-avoiding a-trous wavelet filter of Dammertz et al. 2010
// (HPG 2010): B3-spline 5x5 kernel at step 2^level, weights
// exp(-||I(p) - I(q)||^2 / sigma^2) on colour, normal and world position, multiplied.
// Formulas and guards: passes/include/hush/passes/eaw/atrous.hpp. One invocation
// filters a 4x4 block of the a-trous lattice (common/atrous_lattice.glsl): 64 texels
// per resource for 16 pixels, 1.2-1.3x faster on lavapipe than 2x2 blocks (36 for 4;
// docs/passes/atrous-lattice.md).
#include "common/grid.glsl"
#define HUSH_ATROUS_BLOCK 4
#include "common/atrous_lattice.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D color;      // rgb filtered, a copied
layout(set = 0, binding = 1) uniform texture2D normal;     // xyz, 0 where no surface
layout(set = 0, binding = 2) uniform texture2D position;   // world xyz
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D filtered;
layout(set = 0, binding = 4) uniform texture2D depth;      // linear depth (read when depthRelative)

layout(push_constant) uniform Params {
    int step;          // 2^level, capped so that offsets stay in int range
    float sigmaRt2;    // (2^-level sigma_rt)^2, >= 1e-30; relative to the local mean luminance squared when colorRelative
    float sigmaN2;     // >= 1e-30
    float sigmaX2;     // >= 1e-30
    uint depthRelative;   // 1: position distances are divided by the centre's depth
    uint colorRelative;   // 1: colour distances are divided by the local mean luminance
} params;

const float kKernel[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);

// The invocation's 8x8 lattice points; a normal of 0 marks a point outside the image,
// skipped like one without a surface.
vec4 tapColour[kLatticePoints];
vec3 tapNormal[kLatticePoints];
vec3 tapPosition[kLatticePoints];

bool hasSurface(vec3 n) {
    return dot(n, n) > 1e-6;
}

float luminance(vec3 c) {
    return abs(dot(c, vec3(0.2126, 0.7152, 0.0722)));
}

float squaredDistance(vec3 a, vec3 b) {
    vec3 d = a - b;
    return dot(d, d);
}

float kernelWeight(int t) {
    return kKernel[abs(t % 5 - 2)] * kKernel[abs(t / 5 - 2)];
}

void loadLattice(ivec2 origin, ivec2 size) {
    [[unroll]] for (int i = 0; i < kLatticePoints; ++i) {
        ivec2 q = latticePixel(origin, params.step, i);
        bool inside = hushInside(q, size);
        tapColour[i] = inside ? texelFetch(color, q, 0) : vec4(0.0);
        tapNormal[i] = inside ? texelFetch(normal, q, 0).xyz : vec3(0.0);
        tapPosition[i] = inside ? texelFetch(position, q, 0).xyz : vec3(0.0);
    }
}

// Pixel b of the block, its centre at lattice point c, inside the image.
vec4 filterPixel(ivec2 p, int b) {
    int c = latticeCentre(b);
    vec4 centre = tapColour[c];
    vec3 nP = tapNormal[c];
    if (!hasSurface(nP)) {
        return centre;
    }
    vec3 xP = tapPosition[c];
    // Scale-free position weight: ||x_p - x_q|| / z_p, so that one sigma suits a scene
    // modelled in millimetres and one in metres (docs/passes/eaw.md).
    float xScale2 = 1.0;
    if (params.depthRelative != 0u) {
        float z = max(abs(texelFetch(depth, p, 0).x), 1e-20);
        xScale2 = z * z;
    }
    // The scale-free colour weight needs the taps' mean luminance before any weight
    // (docs/passes/eaw.md).
    float luminanceSum = 0.0, kernelSum = 0.0;
    [[unroll]] for (int t = 0; t < 25; ++t) {
        int q = latticeTap(b, t);
        float k = t != 12 && !hasSurface(tapNormal[q]) ? 0.0 : kernelWeight(t);
        luminanceSum += k * luminance(tapColour[q].rgb);
        kernelSum += k;
    }
    // Scale-free: distances over the local mean luminance (floored at 1e-20), as the
    // position weight is over depth; a frame 1000x brighter is filtered alike.
    float sigmaRt2 = params.sigmaRt2;
    if (params.colorRelative != 0u) {
        float l = max(luminanceSum / kernelSum, 1e-20);
        sigmaRt2 = max(sigmaRt2 * l * l, 1e-30);
    }

    vec3 colourSum = vec3(0.0);
    float weightSum = 0.0;
    [[unroll]] for (int t = 0; t < 25; ++t) {
        int q = latticeTap(b, t);
        // Without a surface (or off the image) a tap weighs 0 by a select, not a
        // `continue`: lavapipe runs the branch-free loop 4-9 % faster (docs/benchmarks.md).
        bool counts = t == 12 || hasSurface(tapNormal[q]);
        vec3 cQ = tapColour[q].rgb;
        float w = 1.0;
        if (t != 12) {
            // w_rt w_n w_x as one exponential of the summed exponents.
            w = exp(-(squaredDistance(centre.rgb, cQ) / sigmaRt2 + squaredDistance(nP, tapNormal[q]) / params.sigmaN2 +
                      squaredDistance(xP, tapPosition[q]) / (params.sigmaX2 * xScale2)));
        }
        float hw = counts ? kernelWeight(t) * w : 0.0;
        colourSum += hw * cQ;
        weightSum += hw;
    }
    // weightSum >= (3/8)^2 from the centre tap.
    return vec4(colourSum / weightSum, centre.a);
}

void main() {
    ivec2 size = imageSize(filtered);
    ivec2 origin = latticeOrigin(params.step);
    if (!hushInside(latticePixel(origin, params.step, latticeCentre(0)), size)) {
        return;   // the block's first pixel is its smallest: the whole block is outside
    }
    loadLattice(origin, size);
    [[unroll]] for (int b = 0; b < kLatticeBlock * kLatticeBlock; ++b) {
        ivec2 p = latticePixel(origin, params.step, latticeCentre(b));
        if (hushInside(p, size)) {
            imageStore(filtered, p, filterPixel(p, b));
        }
    }
}
