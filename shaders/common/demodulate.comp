#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// illumination = radiance / demodulationFactor(albedo) (SVGF Sec. 3, BMFR Sec. 3).
#include "common/grid.glsl"
#include "common/demodulation.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D radiance;
layout(set = 0, binding = 1) uniform texture2D albedo;
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D illumination;

layout(push_constant) uniform Params {
    float eps;
} params;

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(illumination))) {
        return;
    }
    vec3 factor = demodulationFactor(texelFetch(albedo, p, 0).rgb, params.eps);
    imageStore(illumination, p, vec4(texelFetch(radiance, p, 0).rgb / factor, 1.0));
}
