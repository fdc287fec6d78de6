#version 450
// values[i] += i + 1 for i < count: a read-modify-write that needs a barrier
// between consecutive dispatches.
layout(local_size_x = 64) in;

layout(set = 0, binding = 0, std430) buffer Values { uint values[]; };
layout(push_constant) uniform Params { uint count; } params;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < params.count) {
        values[i] += i + 1u;
    }
}
