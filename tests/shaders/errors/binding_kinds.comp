#version 450
// A layout for the bind-group mismatch tests: one binding of each common kind.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba16f) uniform writeonly image2D outImage;
layout(set = 0, binding = 1, std430) buffer DataBlock { float values[]; } data;
layout(set = 0, binding = 2) uniform texture2D inputTex;
layout(set = 0, binding = 3) uniform sampler inputSampler;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    vec4 v = textureLod(sampler2D(inputTex, inputSampler), vec2(0.5), 0.0);
    imageStore(outImage, p, v * data.values[0]);
}
