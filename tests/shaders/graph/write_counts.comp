#version 450
// Render graph indirect-dispatch tests: writes workgroup counts (x, y, z) for a later
// indirect dispatch, as a classifying pass would.
layout(local_size_x = 1) in;

layout(set = 0, binding = 0, std430) writeonly buffer CountsBlock { uint values[]; } counts;

layout(push_constant) uniform Params {
    uint x;
    uint y;
    uint z;
} params;

void main() {
    counts.values[0] = params.x;
    counts.values[1] = params.y;
    counts.values[2] = params.z;
}
