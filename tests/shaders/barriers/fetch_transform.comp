#version 450
#extension GL_EXT_samplerless_texture_functions : require
// dst = src * 2 + 1, reading src as a sampled texture (texelFetch) and writing dst as
// a storage image: the two image layouts a texture moves between.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D src;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2D dst;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(dst)))) {
        return;
    }
    imageStore(dst, p, texelFetch(src, p, 0) * 2.0 + 1.0);
}
