#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Mara et al. 2017 stage 3, matte temporal (seed 000 Sec. 3.4, Eq. 11): last frame's
// history at p + 0.5 + motion, trusted by how close last frame's world position
// there is to this pixel's (shaders/mara/temporal.glsl).
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D current;            // matte irradiance, rgb
layout(set = 0, binding = 1) uniform texture2D motion;             // previous - current pixel, xy
layout(set = 0, binding = 2) uniform texture2D position;           // world xyz
layout(set = 0, binding = 3) uniform texture2D history;            // last frame's pre-bilateral output
layout(set = 0, binding = 4) uniform texture2D position_history;   // last frame's position
layout(set = 0, binding = 5, rgba32f) uniform writeonly image2D temporal;

layout(push_constant) uniform Params {
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
    vec2 q = vec2(p) + 0.5 + texelFetch(motion, p, 0).xy;
    bool inside = all(greaterThanEqual(q, vec2(0.0))) && all(lessThan(q, vec2(size)));
    imageStore(temporal, p, maraTemporal(p, size, q, params.historyValid != 0u && inside,
                                         texelFetch(position, p, 0).xyz, params.hysteresis, params.d0, params.d1,
                                         params.metresPerUnit));
}
