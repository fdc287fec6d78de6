// RDAE 2x2 nearest-neighbour upsampling (Chaitanya et al. 2017, Fig. 2): level k + 1
// to k, per channel. Included by upsample.comp (rgba16f) and upsample_rgba32f.comp.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "rdae/tensor.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform texture2D features;
layout(set = 0, binding = 1, HUSH_TENSOR_FORMAT) uniform writeonly image2D upsampled;

layout(push_constant) uniform Params {
    ivec2 size;   // the output's block extent; the input's is half of it
    uint tiles;
} params;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    uint block = gl_GlobalInvocationID.z;
    if (any(greaterThanEqual(p, params.size))) {
        return;
    }
    vec4 v = texelFetch(features, rdaeTexel(p / 2, block, params.tiles, params.size / 2), 0);
    imageStore(upsampled, rdaeTexel(p, block, params.tiles, params.size), v);
}
