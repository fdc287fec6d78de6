#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// The RDAE's output layer back to illumination: crop the padded tensor to the frame,
// undo the 0.2 power of the input (x^5 of the non-negative part), stay finite.
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D features;   // 3 channels, block 0 at tile (0, 0)
layout(set = 0, binding = 1, rgba32f) uniform writeonly image2D illumination;

const float kInversePower = 5.0;
const float kLargest = 65504.0;   // what the inputs are clamped to (sanitize)

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(illumination))) {
        return;
    }
    vec3 x = texelFetch(features, p, 0).rgb;
    x = clamp(mix(x, vec3(0.0), isnan(x)), vec3(0.0), vec3(9.2));   // 9.2^5 > 65504
    imageStore(illumination, p, vec4(min(pow(x, vec3(kInversePower)), vec3(kLargest)), 1.0));
}
