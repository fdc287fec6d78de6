#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// SVGF Sec. 4.4, "Luminance": the 3x3 Gaussian g3x3 of the luminance variance that
// steers w_l (Eq. 5). Weights (1/4, 1/2, 1/4) per axis, renormalised over the taps
// inside the image, so the border needs no clamp and a constant stays constant.
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D illum_variance;
layout(set = 0, binding = 1, r32f) uniform writeonly image2D prefiltered_variance;

const float kGauss[2] = float[2](0.5, 0.25);

void main() {
    ivec2 p = hushPixel();
    ivec2 size = imageSize(prefiltered_variance);
    if (!hushInside(p, size)) {
        return;
    }
    float sum = 0.0;
    float weightSum = 0.0;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = p + ivec2(dx, dy);
            if (!hushInside(q, size)) {
                continue;
            }
            float g = kGauss[abs(dx)] * kGauss[abs(dy)];
            sum += g * texelFetch(illum_variance, q, 0).a;
            weightSum += g;
        }
    }
    // The centre is always inside: weightSum >= 1/4.
    imageStore(prefiltered_variance, p, vec4(sum / weightSum, 0.0, 0.0, 0.0));
}
