#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// illumination = (radiance - emission) / demodulationFactor(albedo) (SVGF Sec. 3, BMFR
// Sec. 3). Emission seen directly is noise-free: it is taken out before filtering
// and added back by common/remodulate.comp.
#include "common/grid.glsl"
#include "common/demodulation.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D radiance;
layout(set = 0, binding = 1) uniform texture2D albedo;
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D illumination;
layout(set = 0, binding = 3) uniform texture2D emission;   // read when hasEmission

layout(push_constant) uniform Params {
    float eps;
    uint hasEmission;
} params;

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(illumination))) {
        return;
    }
    vec3 factor = demodulationFactor(texelFetch(albedo, p, 0).rgb, params.eps);
    vec3 r = texelFetch(radiance, p, 0).rgb;
    if (params.hasEmission != 0u) {
        r = max(r - texelFetch(emission, p, 0).rgb, vec3(0.0));
    }
    imageStore(illumination, p, vec4(r / factor, 1.0));
}
