#version 450
// Every binding kind hush reflects, in two descriptor sets, with push constants and a
// non-square workgroup. tests/rhi/test_reflection.cpp lists what each must reflect to.
// Set 1 is declared out of binding order (reflection sorts by binding).
layout(local_size_x = 4, local_size_y = 2, local_size_z = 1) in;

// set 0
layout(set = 0, binding = 0) uniform ParamsBlock { vec4 tint; } params;
layout(set = 0, binding = 1, std430) buffer RWBlock { float rw[]; };
layout(set = 0, binding = 2, std430) readonly buffer ROBlock { float ro[]; } roData;
layout(set = 0, binding = 3) uniform texture2D sampledTex;
layout(set = 0, binding = 4) uniform sampler plainSampler;
layout(set = 0, binding = 5) uniform sampler2D combinedTex;
layout(set = 0, binding = 6, rgba16f) uniform readonly image2D imgRead;
layout(set = 0, binding = 7, r32f) uniform writeonly image2D imgWrite;
layout(set = 0, binding = 8, rgba8) uniform image2D imgReadWrite;
layout(set = 0, binding = 9, r32ui) uniform uimage2D counts;

// set 1
layout(set = 1, binding = 5, std430) buffer Histogram { uint bins[]; } histogram;
layout(set = 1, binding = 0, r8) uniform writeonly image2D maskOut;
layout(set = 1, binding = 2, rg16f) uniform readonly image2D motionIn;
layout(set = 1, binding = 3, rg32f) uniform writeonly image2D momentsOut;
layout(set = 1, binding = 4, r16f) uniform readonly image2D depthIn;

layout(push_constant) uniform Push {
    vec4 a;   // 16 bytes
    uint b;   // + 4: 20 bytes in std430
} push;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    uint i = gl_GlobalInvocationID.x;
    vec4 s = textureLod(sampler2D(sampledTex, plainSampler), vec2(0.5), 0.0) + textureLod(combinedTex, vec2(0.5), 0.0);
    vec4 r = imageLoad(imgRead, p) + imageLoad(imgReadWrite, p) + params.tint + push.a + s;
    rw[i] = roData.ro[i] * r.x;
    imageStore(imgWrite, p, vec4(r.y));
    imageStore(imgReadWrite, p, r);
    imageAtomicAdd(counts, p, push.b);
    atomicAdd(histogram.bins[i], 1u);
    imageStore(maskOut, p, vec4(imageLoad(motionIn, p).x + imageLoad(depthIn, p).x));
    imageStore(momentsOut, p, vec4(r.zw, 0.0, 0.0));
}
