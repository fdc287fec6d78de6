#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Mara et al. 2017's composite (seed 000 Sec. 3.1-3.3, Eq. 9 and 10): the filtered
// indirect terms with the material put back, at the mirror direction w_s:
//   radiance = direct + (1 - F)^2 * albedo * matte + F * glossy
//   F = F0 + (1 - F0) (1 - n.v)^5 (Schlick at w_s, where h = n), 0 without a specular
//   layer (F0 = 0), as the tracer's BRDF (docs/tracer.md); v = normalize(camera - X)
// `glossy` is read when hasGlossy (without it, the graph culls the glossy branch).
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D direct;
layout(set = 0, binding = 1) uniform texture2D matte;
layout(set = 0, binding = 2) uniform texture2D glossy;
layout(set = 0, binding = 3) uniform texture2D albedo;
layout(set = 0, binding = 4) uniform texture2D specular;
layout(set = 0, binding = 5) uniform texture2D normal_depth;
layout(set = 0, binding = 6) uniform texture2D position;
layout(set = 0, binding = 7, rgba32f) uniform writeonly image2D radiance;

layout(push_constant) uniform Params {
    vec4 cameraPosition;   // xyz world
    uint hasGlossy;
} params;

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(radiance))) {
        return;
    }
    vec3 result = texelFetch(direct, p, 0).rgb;
    vec3 n = texelFetch(normal_depth, p, 0).xyz;
    if (dot(n, n) > 1e-6) {
        vec3 f0 = texelFetch(specular, p, 0).rgb;
        vec3 toCamera = params.cameraPosition.xyz - texelFetch(position, p, 0).xyz;
        float len = length(toCamera);
        float cosine = len > 1e-30 ? clamp(dot(n, toCamera / len), 0.0, 1.0) : 1.0;
        float c5 = pow(1.0 - cosine, 5.0);
        vec3 fresnel = any(greaterThan(f0, vec3(0.0))) ? f0 + (1.0 - f0) * c5 : vec3(0.0);
        vec3 oneMinusF = 1.0 - fresnel;
        result += oneMinusF * oneMinusF * texelFetch(albedo, p, 0).rgb * texelFetch(matte, p, 0).rgb;
        if (params.hasGlossy != 0u) {
            result += fresnel * texelFetch(glossy, p, 0).rgb;
        }
    }
    imageStore(radiance, p, vec4(result, 1.0));
}
