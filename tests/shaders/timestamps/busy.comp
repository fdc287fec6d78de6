#version 450
// Enough arithmetic per invocation that a 64x64 dispatch takes measurable time.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std430) buffer Out { float values[]; };
layout(push_constant) uniform Params { uint width; uint iterations; } params;

void main() {
    uvec2 p = gl_GlobalInvocationID.xy;
    float v = float(p.x + p.y * params.width) * 1e-3;
    for (uint k = 0u; k < params.iterations; ++k) {
        v = fract(v * 1.618034 + 0.5) + sin(v);
    }
    values[p.y * params.width + p.x] = v;
}
