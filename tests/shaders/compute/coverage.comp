#version 450
// Writes 1 + x + width * y to cell (x, y) of a width x height grid, nothing else:
// checks that dispatchThreads covers an odd-sized grid exactly.
layout(local_size_x = 8, local_size_y = 4) in;

layout(set = 0, binding = 0, std430) buffer Cells { uint cells[]; };
layout(push_constant) uniform Params {
    uint width;
    uint height;
} params;

void main() {
    uvec2 p = gl_GlobalInvocationID.xy;
    if (p.x < params.width && p.y < params.height) {
        cells[p.y * params.width + p.x] = 1u + p.x + params.width * p.y;
    }
}
