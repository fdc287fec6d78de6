#version 450
// The other shader of the shared explicit layout:
//   sums[y * width + x] += src.r * push.factor
// It uses bindings 0 and 2 of the shared layout, and 8 of its 16 push-constant bytes.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba32f) uniform readonly image2D src;
layout(set = 0, binding = 2, std430) buffer Sums { float sums[]; };
layout(push_constant) uniform Push { float factor; uint width; } push;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(src)))) {
        return;
    }
    uint i = uint(p.y) * push.width + uint(p.x);
    sums[i] += imageLoad(src, p).r * push.factor;
}
