#version 450
// dst = src, texel by texel, through imageLoad / imageStore in format rg16f.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rg16f) uniform readonly image2D src;
layout(set = 0, binding = 1, rg16f) uniform writeonly image2D dst;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(src)))) {
        return;
    }
    imageStore(dst, p, imageLoad(src, p));
}
