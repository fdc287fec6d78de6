#version 450
// Bandwidth probe over storage buffers: one vec4 (16 bytes) read and one written
// per invocation, the buffer counterpart of copy_rgba32f. Used by
// samples/bench/bandwidth.cpp.

// 256 per workgroup keeps a 3840x2160 dispatch (8.3M invocations) within the
// 65535 workgroups per dimension that every Vulkan device supports.
layout(local_size_x = 256) in;

layout(set = 0, binding = 0, std430) readonly buffer Src { vec4 src[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Dst { vec4 dst[]; };

// The element count: a dispatch covers whole workgroups, so the tail is skipped.
layout(push_constant) uniform Params { uint count; } params;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= params.count) {
        return;
    }
    dst[i] = src[i];
}
