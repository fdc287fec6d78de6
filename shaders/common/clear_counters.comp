#version 450
// Zeroes a buffer of counters (the sanitiser's, each frame). A shader rather than a
// buffer fill, so that the graph sees one kind of access (storage write) on it.
layout(local_size_x = 64) in;

layout(set = 0, binding = 0, std430) writeonly buffer CountsBlock { uint values[]; } counts;

layout(push_constant) uniform Params {
    uint count;
} params;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < params.count) {
        counts.values[i] = 0u;
    }
}
