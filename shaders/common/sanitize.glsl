// Non-finite sanitisation (DESIGN.md's numerical contract): NaN and Inf never pass
// a chain's first pass. Each component is replaced by `replacement` when it is not
// finite, then clamped to [lo, hi]; the pixel is counted (counts.values[slot]) when any of
// its components was replaced. The including shader declares `dst`, the output image
// (binding 1), with its format qualifier first.
#ifndef HUSH_COMMON_SANITIZE_GLSL
#define HUSH_COMMON_SANITIZE_GLSL
#extension GL_EXT_control_flow_attributes : require
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

const int kRow = 4;   // pixels per invocation, along x (sanitize.cpp: kSanitizeRow)

void main() {
    ivec2 size = imageSize(dst);
    ivec2 first = ivec2(gl_GlobalInvocationID.x * kRow, gl_GlobalInvocationID.y);
    if (!hushInside(first, size)) {
        return;
    }
    uint replaced = 0u;
    [[unroll]] for (int k = 0; k < kRow; ++k) {
        ivec2 p = first + ivec2(k, 0);
        if (p.x < size.x) {
            vec4 v = texelFetch(src, p, 0);
            bvec4 bad = bvec4(uvec4(isnan(v)) | uvec4(isinf(v)));
            replaced += any(bad) ? 1u : 0u;
            vec4 finite = mix(v, vec4(params.replacement), bad);
            imageStore(dst, p, clamp(finite, vec4(params.lo), vec4(params.hi)));
        }
    }
    if (replaced != 0u) {
        atomicAdd(counts.values[params.slot], replaced);
    }
}
#endif
