#version 450
#extension GL_EXT_samplerless_texture_functions : require
// For texel (x, y) of a W x H texture, writes four samples to out[(y * W + x) * 4 + k]:
//   0: texture(sampler2D(tex, nearestSampler), centre of (x, y))        -> texel (x, y)
//   1: texture(combinedLinear, between (x, y) and (x + 1, y))           -> mean of the two (clamped at the edge)
//   2: texelFetch(tex, (x, y))                                          -> texel (x, y)
//   3: texture(combinedLinear, corner shared by (x..x+1, y..y+1))       -> mean of four (clamped)
layout(local_size_x = 8, local_size_y = 4) in;

layout(set = 0, binding = 0) uniform texture2D tex;
layout(set = 0, binding = 1) uniform sampler nearestSampler;
layout(set = 0, binding = 2) uniform sampler2D combinedLinear;
layout(set = 0, binding = 3, std430) writeonly buffer Samples { vec4 samples[]; };

void main() {
    ivec2 size = textureSize(tex, 0);
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= size.x || p.y >= size.y) {
        return;
    }
    vec2 inv = 1.0 / vec2(size);
    uint base = (uint(p.y) * uint(size.x) + uint(p.x)) * 4u;
    samples[base + 0u] = textureLod(sampler2D(tex, nearestSampler), (vec2(p) + 0.5) * inv, 0.0);
    samples[base + 1u] = textureLod(combinedLinear, (vec2(p) + vec2(1.0, 0.5)) * inv, 0.0);
    samples[base + 2u] = texelFetch(tex, p, 0);
    samples[base + 3u] = textureLod(combinedLinear, (vec2(p) + vec2(1.0, 1.0)) * inv, 0.0);
}
