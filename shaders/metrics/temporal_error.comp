#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Temporal error's partial sums (passes/metrics/temporal_error.hpp; SVGF, Schied et
// al. 2017, Sec. 5.4 and Fig. 10: "the average luminance of the per-pixel
// differences" between consecutive frames). Per pixel: the Rec. 709 luminance of
// the absolute RGB difference, dot(|current - previous|, (0.2126, 0.7152, 0.0722)).
// A pixel with a non-finite RGB component in either frame adds nothing and is
// counted instead. Partial: (luminance sum, finite pixels, non-finite pixels, 0).
#include "metrics/reduce.glsl"

layout(set = 0, binding = 0) uniform texture2D current;
layout(set = 0, binding = 1) uniform texture2D previous;

const vec3 kRec709Luminance = vec3(0.2126, 0.7152, 0.0722);

void main() {
    const ivec2 size = textureSize(current, 0);
    const ivec2 stride = hushGridStride();
    vec4 sums = vec4(0.0);
    for (int y = hushGridStart().y; y < size.y; y += stride.y) {
        for (int x = hushGridStart().x; x < size.x; x += stride.x) {
            const vec3 a = texelFetch(current, ivec2(x, y), 0).rgb;
            const vec3 b = texelFetch(previous, ivec2(x, y), 0).rgb;
            if (!hushAllFinite(a) || !hushAllFinite(b)) {
                sums.z += 1.0;
                continue;
            }
            sums.x += dot(abs(a - b), kRec709Luminance);
            sums.y += 1.0;
        }
    }
    hushStorePartial(sums);
}
