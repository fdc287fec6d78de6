#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Mara et al. 2017 stage 8, glossy temporal (seed 000 Sec. 3.4): the reflection seen
// at p was, last frame, where last frame's camera saw the virtual (reflected)
// position, not where the mirror surface was (Zimmer et al. 2015); the same
// confidence and clamp as the matte stage (shaders/mara/temporal.glsl), on the
// virtual positions.
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D current;            // glossy radiance, rgb
layout(set = 0, binding = 1) uniform texture2D virtualpos;         // world xyz of the reflected point
layout(set = 0, binding = 2) uniform texture2D history;            // last frame's output
layout(set = 0, binding = 3) uniform texture2D position_history;   // last frame's virtualpos
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D temporal;

layout(push_constant) uniform Params {
    vec4 previousViewProjection[4];   // columns of last frame's projection * view
    float hysteresis;
    float d0;
    float d1;
    float metresPerUnit;
    uint historyValid;
} params;

#include "mara/temporal.glsl"

void main() {
    ivec2 p = hushPixel();
    ivec2 size = imageSize(temporal);
    if (!hushInside(p, size)) {
        return;
    }
    vec3 v = texelFetch(virtualpos, p, 0).xyz;
    mat4 m = mat4(params.previousViewProjection[0], params.previousViewProjection[1],
                  params.previousViewProjection[2], params.previousViewProjection[3]);
    vec4 clip = m * vec4(v, 1.0);
    bool inFront = clip.w > 1e-6;
    // Vulkan NDC: x right, y down, both -1..1 across the image.
    vec2 q = (clip.xy / max(clip.w, 1e-6) * 0.5 + 0.5) * vec2(size);
    bool inside = inFront && all(greaterThanEqual(q, vec2(0.0))) && all(lessThan(q, vec2(size)));
    imageStore(temporal, p, maraTemporal(p, size, q, params.historyValid != 0u && inside, v, params.hysteresis,
                                         params.d0, params.d1, params.metresPerUnit));
}
