#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
// SVGF Sec. 4.4, "Luminance": the 3x3 Gaussian g3x3 of the luminance variance that
// steers w_l (Eq. 5). Weights (1/4, 1/2, 1/4) per axis, renormalised over the taps
// inside the image, so the border needs no clamp and a constant stays constant.
//
// One invocation filters a row of kRow pixels along x, whose 3x3 windows share
// their texels: (kRow + 2) x 3 fetches for kRow pixels instead of kRow x 9. Taps off
// the image are fetched clamped and weigh 0 by a select, not a branch (as in
// svgf/atrous.comp); each pixel adds its taps in the one-pixel loop's order. The host
// dispatches ceil(width / kRow) columns (variance_prefilter.cpp: kPrefilterRow).
#include "common/grid.glsl"

const int kRow = 4;

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D illum_variance;
layout(set = 0, binding = 1, r32f) uniform writeonly image2D prefiltered_variance;

const float kGauss[2] = float[2](0.5, 0.25);

void main() {
    ivec2 size = imageSize(prefiltered_variance);
    ivec2 first = ivec2(gl_GlobalInvocationID.x * kRow, gl_GlobalInvocationID.y);
    if (!hushInside(first, size)) {
        return;
    }
    float sum[kRow];
    float weightSum[kRow];
    [[unroll]] for (int k = 0; k < kRow; ++k) {
        sum[k] = 0.0;
        weightSum[k] = 0.0;
    }
    [[unroll]] for (int dy = -1; dy <= 1; ++dy) {
        [[unroll]] for (int column = 0; column < kRow + 2; ++column) {
            ivec2 q = first + ivec2(column - 1, dy);
            bool inside = hushInside(q, size);
            float v = texelFetch(illum_variance, clamp(q, ivec2(0), size - 1), 0).a;
            [[unroll]] for (int k = 0; k < kRow; ++k) {
                int dx = column - 1 - k;
                if (dx < -1 || dx > 1) {
                    continue;   // decided at compile time: the loops are unrolled
                }
                float g = inside ? kGauss[abs(dx)] * kGauss[abs(dy)] : 0.0;
                sum[k] += g * v;
                weightSum[k] += g;
            }
        }
    }
    [[unroll]] for (int k = 0; k < kRow; ++k) {
        ivec2 p = first + ivec2(k, 0);
        if (hushInside(p, size)) {
            // The centre is always inside: weightSum >= 1/4.
            imageStore(prefiltered_variance, p, vec4(sum[k] / weightSum[k], 0.0, 0.0, 0.0));
        }
    }
}
