#version 450
// One of two shaders sharing an explicit layout (tests/rhi/test_layouts.cpp):
//   dst = src * params.scale + push.offset
// It uses bindings 0, 1 and 3 of the shared layout, not 2.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba32f) uniform readonly image2D src;
layout(set = 0, binding = 1, rgba32f) uniform writeonly image2D dst;
layout(set = 0, binding = 3) uniform Params { vec4 scale; } params;
layout(push_constant) uniform Push { vec4 offset; } push;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(src)))) {
        return;
    }
    imageStore(dst, p, imageLoad(src, p) * params.scale + push.offset);
}
