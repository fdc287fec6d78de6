#version 450
// values[y * width + x] = values[...] * 2 + uint(image(x, y).z)
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba32f) uniform readonly image2D image;
layout(set = 0, binding = 1, std430) buffer Values { uint values[]; };

void main() {
    ivec2 size = imageSize(image);
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    uint i = uint(p.y) * uint(size.x) + uint(p.x);
    values[i] = values[i] * 2u + uint(imageLoad(image, p).z);
}
