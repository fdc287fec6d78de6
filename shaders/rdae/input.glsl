// The RDAE's input tensor (Chaitanya et al. 2017 Sec. 3.2): 7 channels per pixel,
//   0-2  demodulated noisy colour ("untextured illumination"), raised to 0.2
//   3-4  view-space shading normal, x and y
//   5    linear depth in metres, d / (1 + d)
//   6    roughness (GGX alpha), clamped to [0, 1]
//   7    0 (block padding)
// The power 0.2 is the paper's training transform (Sec. 4.4: input and target raised
// to 0.2); the depth mapping bounds scenes of any scale (docs/passes/rdae.md). The
// padded border repeats the edge pixels. Included by input.comp and input_rgba32f.comp.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "rdae/tensor.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform texture2D illumination;
layout(set = 0, binding = 1) uniform texture2D normal;
layout(set = 0, binding = 2) uniform texture2D depth;
layout(set = 0, binding = 3) uniform texture2D roughness;
layout(set = 0, binding = 4, HUSH_TENSOR_FORMAT) uniform writeonly image2D features;

layout(push_constant) uniform Params {
    vec4 viewRow0;        // rows of the world-to-view rotation
    vec4 viewRow1;
    ivec2 size;           // the tensor's (padded) block extent
    ivec2 image;          // the frame's extent
    uint tiles;
    float metresPerUnit;
} params;

const float kColorPower = 0.2;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, params.size))) {
        return;
    }
    ivec2 q = min(p, params.image - 1);
    vec3 c = pow(max(texelFetch(illumination, q, 0).rgb, vec3(0.0)), vec3(kColorPower));
    vec3 n = texelFetch(normal, q, 0).xyz;
    vec2 nv = vec2(dot(params.viewRow0.xyz, n), dot(params.viewRow1.xyz, n));
    float d = max(texelFetch(depth, q, 0).r * params.metresPerUnit, 0.0);
    float r = clamp(texelFetch(roughness, q, 0).r, 0.0, 1.0);
    imageStore(features, rdaeTexel(p, 0u, params.tiles, params.size), vec4(c, nv.x));
    imageStore(features, rdaeTexel(p, 1u, params.tiles, params.size), vec4(nv.y, d / (1.0 + d), r, 0.0));
}
