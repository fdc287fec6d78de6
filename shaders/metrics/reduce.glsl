// Partial sums on a fixed grid (passes/metrics/partial_sums.hpp). The host always
// dispatches kMetricsGridThreads x kMetricsGridThreads invocations, i.e. 16 x 16
// workgroups of 16 x 16, whatever the image size: each invocation accumulates the
// pixels p = id + k * stride (a grid-stride loop) in fp32, the workgroup adds its
// 256 values in shared memory (a tree, log2(256) = 8 levels), and invocation 0
// writes one vec4 per workgroup. The partial count is therefore fixed at 256, so
// the buffer a node declares stays right when the graph's output size changes, and
// every entry is written each frame. The host adds the 256 partials in double.
// The including shader declares its inputs (bindings 0 and 1).
#ifndef HUSH_METRICS_REDUCE_GLSL
#define HUSH_METRICS_REDUCE_GLSL

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = 2, std430) writeonly buffer PartialsBlock { vec4 values[]; } partials;

const uint kReduceInvocations = 256u;
shared vec4 hushReduceScratch[kReduceInvocations];

// The first pixel this invocation visits, and the step between its pixels.
ivec2 hushGridStart() {
    return ivec2(gl_GlobalInvocationID.xy);
}
ivec2 hushGridStride() {
    return ivec2(gl_NumWorkGroups.xy * gl_WorkGroupSize.xy);
}

// Adds `value` over the workgroup and stores the sum as this workgroup's partial.
// Every invocation of the workgroup must call it (it holds barriers).
void hushStorePartial(vec4 value) {
    const uint i = gl_LocalInvocationIndex;
    hushReduceScratch[i] = value;
    barrier();
    for (uint width = kReduceInvocations / 2u; width > 0u; width /= 2u) {
        if (i < width) {
            hushReduceScratch[i] += hushReduceScratch[i + width];
        }
        barrier();
    }
    if (i == 0u) {
        partials.values[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x] = hushReduceScratch[0];
    }
}

// True when every component is finite (neither NaN nor +-Inf).
bool hushAllFinite(vec3 v) {
    return !any(isnan(v)) && !any(isinf(v));
}

#endif
