#version 450
// Render graph indirect-dispatch tests, run by an indirect dispatch: every invocation
// adds 1 to tally[0], and each workgroup sets bit x + 4 y + 16 z of tally[1] (ids
// below 4, 4, 2), so the test sees how many and which workgroups ran. It also reads
// the counts it was dispatched by (counts[0] into tally[2]), as a listed-tiles shader
// reads its list.
layout(local_size_x = 4, local_size_y = 2) in;

layout(set = 0, binding = 0, std430) readonly buffer CountsBlock { uint values[]; } counts;
layout(set = 0, binding = 1, std430) buffer TallyBlock { uint values[]; } tally;

void main() {
    atomicAdd(tally.values[0], 1u);
    if (gl_LocalInvocationIndex == 0u) {
        uvec3 g = gl_WorkGroupID;
        atomicOr(tally.values[1], 1u << (g.x + 4u * g.y + 16u * g.z));
        tally.values[2] = counts.values[0];
    }
}
