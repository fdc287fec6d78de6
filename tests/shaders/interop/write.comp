#version 450
// image(x, y) = (x, y, x * y, 1);  values[y * width + x] = x + 1000 * y
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba32f) uniform writeonly image2D image;
layout(set = 0, binding = 1, std430) writeonly buffer Values { uint values[]; };

void main() {
    ivec2 size = imageSize(image);
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    imageStore(image, p, vec4(float(p.x), float(p.y), float(p.x * p.y), 1.0));
    values[uint(p.y) * uint(size.x) + uint(p.x)] = uint(p.x) + 1000u * uint(p.y);
}
