#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
// SVGF Sec. 4.4, "Luminance": the 3x3 Gaussian g3x3 of the luminance variance that
// steers w_l (Eq. 5). Weights (1/4, 1/2, 1/4) per axis, renormalised over the taps
// inside the image, so the border needs no clamp and a constant stays constant.
//
// One invocation filters a kBlock x kBlock block of pixels, whose 3x3 windows share
// their texels: (kBlock + 2)^2 fetches for kBlock^2 pixels (100 for 64) instead of 9
// per pixel. 8 measured fastest on lavapipe (1.55x rows of 4; 4x4 blocks 1.3x). Taps off the image are fetched clamped and weigh 0 by a select, not a
// branch (as in svgf/atrous.comp); each pixel adds its taps in the one-pixel loop's
// order (rows, then columns). The host dispatches ceil(size / kBlock) invocations
// per axis (variance_prefilter.cpp: kPrefilterBlock).
#include "common/grid.glsl"

const int kBlock = 8;
const int kBlockPixels = kBlock * kBlock;

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D illum_variance;
layout(set = 0, binding = 1, r32f) uniform writeonly image2D prefiltered_variance;

const float kGauss[2] = float[2](0.5, 0.25);

void main() {
    ivec2 size = imageSize(prefiltered_variance);
    ivec2 first = ivec2(gl_GlobalInvocationID.xy) * kBlock;
    if (!hushInside(first, size)) {
        return;
    }
    float sum[kBlockPixels];
    float weightSum[kBlockPixels];
    [[unroll]] for (int k = 0; k < kBlockPixels; ++k) {
        sum[k] = 0.0;
        weightSum[k] = 0.0;
    }
    [[unroll]] for (int row = 0; row < kBlock + 2; ++row) {
        [[unroll]] for (int column = 0; column < kBlock + 2; ++column) {
            ivec2 q = first + ivec2(column - 1, row - 1);
            bool inside = hushInside(q, size);
            float v = texelFetch(illum_variance, clamp(q, ivec2(0), size - 1), 0).a;
            [[unroll]] for (int k = 0; k < kBlockPixels; ++k) {
                int dx = column - 1 - k % kBlock;
                int dy = row - 1 - k / kBlock;
                if (dx < -1 || dx > 1 || dy < -1 || dy > 1) {
                    continue;   // decided at compile time: the loops are unrolled
                }
                float g = inside ? kGauss[abs(dx)] * kGauss[abs(dy)] : 0.0;
                sum[k] += g * v;
                weightSum[k] += g;
            }
        }
    }
    [[unroll]] for (int k = 0; k < kBlockPixels; ++k) {
        ivec2 p = first + ivec2(k % kBlock, k / kBlock);
        if (hushInside(p, size)) {
            // The centre is always inside: weightSum >= 1/4.
            imageStore(prefiltered_variance, p, vec4(sum[k] / weightSum[k], 0.0, 0.0, 0.0));
        }
    }
}
