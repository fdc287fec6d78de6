#version 450
// Specialization constants (ComputePipelineDesc::constants): one of each supported
// type, ids not in declaration order; the shader writes their values out, and a loop
// bound by one of them, so that a test reads back what the pipeline was made with.
layout(local_size_x = 1) in;

layout(constant_id = 3) const uint count = 4u;
layout(constant_id = 1) const int offset = -2;
layout(constant_id = 7) const float scale = 0.5;

layout(set = 0, binding = 0, std430) writeonly buffer OutBlock { uint values[]; } result;

void main() {
    result.values[0] = count;
    result.values[1] = uint(offset);
    result.values[2] = floatBitsToUint(scale);
    uint sum = 0u;
    for (uint i = 0u; i < count; ++i) sum += i;
    result.values[3] = sum;
}
