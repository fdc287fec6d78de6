// RDAE 2x2 max pooling (Chaitanya et al. 2017, Fig. 2): level k to k + 1, per channel.
// Included by pool.comp (rgba16f) and pool_rgba32f.comp.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "rdae/tensor.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform texture2D features;
layout(set = 0, binding = 1, HUSH_TENSOR_FORMAT) uniform writeonly image2D pooled;

layout(push_constant) uniform Params {
    ivec2 size;   // the output's block extent; the input's is twice it
    uint tiles;   // same channels in and out, so the same grid
} params;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    uint block = gl_GlobalInvocationID.z;
    if (any(greaterThanEqual(p, params.size))) {
        return;
    }
    ivec2 inSize = 2 * params.size;
    ivec2 q = 2 * p;
    vec4 m = texelFetch(features, rdaeTexel(q, block, params.tiles, inSize), 0);
    m = max(m, texelFetch(features, rdaeTexel(q + ivec2(1, 0), block, params.tiles, inSize), 0));
    m = max(m, texelFetch(features, rdaeTexel(q + ivec2(0, 1), block, params.tiles, inSize), 0));
    m = max(m, texelFetch(features, rdaeTexel(q + ivec2(1, 1), block, params.tiles, inSize), 0));
    imageStore(pooled, rdaeTexel(p, block, params.tiles, params.size), m);
}
