#version 450
// Compute roofline probe: `iterations` rounds of 8 independent vec4 multiply-adds per
// invocation (64 flops a round), so that the device's arithmetic, not its memory,
// sets the time. The sums are written out so that nothing is optimised away, and
// checked on the host (fma_probe.cpp): every invocation computes the same value.
layout(local_size_x = 64) in;

layout(set = 0, binding = 0, std430) writeonly buffer ResultBlock { vec4 values[]; } result;

layout(push_constant) uniform Params {
    uint iterations;
    float scale;   // 0.5: the sums converge instead of overflowing
} params;

void main() {
    vec4 a0 = vec4(1.0), a1 = vec4(2.0), a2 = vec4(3.0), a3 = vec4(4.0);
    vec4 a4 = vec4(5.0), a5 = vec4(6.0), a6 = vec4(7.0), a7 = vec4(8.0);
    const vec4 add = vec4(1.0, 0.5, 0.25, 0.125);
    for (uint i = 0u; i < params.iterations; ++i) {
        a0 = fma(a0, vec4(params.scale), add);
        a1 = fma(a1, vec4(params.scale), add);
        a2 = fma(a2, vec4(params.scale), add);
        a3 = fma(a3, vec4(params.scale), add);
        a4 = fma(a4, vec4(params.scale), add);
        a5 = fma(a5, vec4(params.scale), add);
        a6 = fma(a6, vec4(params.scale), add);
        a7 = fma(a7, vec4(params.scale), add);
    }
    result.values[gl_GlobalInvocationID.x] = a0 + a1 + a2 + a3 + a4 + a5 + a6 + a7;
}
