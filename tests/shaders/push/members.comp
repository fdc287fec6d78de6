#version 450
// Push-constant reflection and rhi::PushConstants: scalars, vectors and an array of
// vectors at std430 offsets; the shader writes them out so that a test can read back
// exactly what PushConstants sent.
layout(local_size_x = 1) in;

layout(set = 0, binding = 0, std430) writeonly buffer OutBlock { uint values[]; } result;

layout(push_constant) uniform Params {
    float scale;       // 0
    int offset;        // 4
    uint flags;        // 8
    vec2 uv;           // 16 (vec2 aligns to 8)
    uvec4 codes[2];    // 32
} params;

void main() {
    result.values[0] = floatBitsToUint(params.scale);
    result.values[1] = uint(params.offset);
    result.values[2] = params.flags;
    result.values[3] = floatBitsToUint(params.uv.x);
    result.values[4] = floatBitsToUint(params.uv.y);
    for (int i = 0; i < 8; ++i) result.values[5 + i] = params.codes[i / 4][i % 4];
}
