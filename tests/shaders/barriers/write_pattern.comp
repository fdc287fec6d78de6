#version 450
// dst(x, y) = (x, y, base.z, base.w) + base.xyxy * 0: small integers, exact in fp16.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba16f) uniform writeonly image2D dst;
layout(push_constant) uniform Params { vec4 base; } params;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(dst)))) {
        return;
    }
    imageStore(dst, p, vec4(float(p.x), float(p.y), params.base.z, params.base.w));
}
