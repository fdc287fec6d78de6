#version 450
// Descriptor sets 0 and 2 with set 1 left empty, no push constants, and a workgroup
// whose three sizes differ (so a swapped axis shows).
layout(local_size_x = 2, local_size_y = 3, local_size_z = 5) in;

layout(set = 0, binding = 0, std430) writeonly buffer Out { float values[]; } outData;
layout(set = 2, binding = 1, rgba32f) uniform readonly image2D source;

void main() {
    outData.values[gl_LocalInvocationIndex] = imageLoad(source, ivec2(gl_GlobalInvocationID.xy)).x;
}
