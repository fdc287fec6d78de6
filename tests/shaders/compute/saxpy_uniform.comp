#version 450
// Parameters from a uniform buffer, input from a read-only storage buffer:
//   y[i] = a * x[i] + b   for i < count
layout(local_size_x = 64) in;

layout(set = 0, binding = 0) uniform Params {
    float a;
    float b;
    uint count;
} params;
layout(set = 0, binding = 1, std430) readonly buffer Inputs { float x[]; };
layout(set = 0, binding = 2, std430) writeonly buffer Outputs { float y[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < params.count) {
        y[i] = params.a * x[i] + params.b;
    }
}
