// Non-finite sanitisation (DESIGN.md's numerical contract): NaN and Inf never pass
// a chain's first pass. Each component is replaced by `replacement` when it is not
// finite, then clamped to [lo, hi]; the pixel is counted (counts.values[slot]) when any of
// its components was replaced. The including shader declares `dst`, the output image
// (binding 1), with its format qualifier first.
#ifndef HUSH_COMMON_SANITIZE_GLSL
#define HUSH_COMMON_SANITIZE_GLSL
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D src;
layout(set = 0, binding = 2, std430) buffer CountsBlock { uint values[]; } counts;

layout(push_constant) uniform Params {
    uint slot;
    float lo;
    float hi;
    float replacement;
} params;

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(dst))) {
        return;
    }
    vec4 v = texelFetch(src, p, 0);
    bvec4 bad = bvec4(uvec4(isnan(v)) | uvec4(isinf(v)));
    if (any(bad)) {
        atomicAdd(counts.values[params.slot], 1u);
    }
    vec4 finite = mix(v, vec4(params.replacement), bad);
    imageStore(dst, p, clamp(finite, vec4(params.lo), vec4(params.hi)));
}
#endif
