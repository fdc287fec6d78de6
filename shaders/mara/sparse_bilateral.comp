#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Mara et al. 2017 stages 4 and 7, the sparse cross-bilateral filter (seed 000 Sec.
// 3.4): `taps` taps on a spiral over a disk (McGuire et al. 2012's ambient-obscurance
// pattern, which Mara et al. 2016 also use), turned per pixel and per frame so that
// the pattern varies in time; Gaussian over the disk (sigma = radius / 2) times the
// plane and normal weights (shaders/mara/bilateral.glsl). Tap i of n:
//   a = (i + 0.5) / n,   angle = 2 pi (spiralTurns a + rotation),   offset = radius a (cos, sin)
//   tap = p + floor(offset + 0.5)
//   rotation = pcg(x + pcg(y + pcg(frame))) / 2^32   (Jarzynski & Olano 2020's PCG hash:
//   integer arithmetic, so the CPU reference reproduces it bit for bit)
// The radius is `radiusPixels` (stage 4: 0.5% of the width), or, with useRadiusMap,
// the r32f `radius` map of the disocclusion stage (stage 7).
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D color;
layout(set = 0, binding = 1) uniform texture2D normal_depth;
layout(set = 0, binding = 2) uniform texture2D position;
layout(set = 0, binding = 3) uniform texture2D radius;   // read with useRadiusMap
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D filtered;

layout(push_constant) uniform Params {
    uint taps;
    float spiralTurns;
    float radiusPixels;
    float planeSigma;
    float normalPower;
    uint useRadiusMap;
    uint frame;
} params;

// normalPower if it is a whole number, else 0 (common/normal_power.glsl).
layout(constant_id = 0) const uint wholeNormalPower = 0u;

#include "mara/bilateral.glsl"

const float kTwoPi = 6.28318530718;

uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

void main() {
    ivec2 p = hushPixel();
    ivec2 size = imageSize(filtered);
    if (!hushInside(p, size)) {
        return;
    }
    vec4 centre = texelFetch(color, p, 0);
    float r = params.useRadiusMap != 0u ? texelFetch(radius, p, 0).x : params.radiusPixels;
    vec4 nd = texelFetch(normal_depth, p, 0);
    if (!maraHasSurface(nd) || !(r > 0.0)) {
        imageStore(filtered, p, centre);
        return;
    }
    MaraCentre c = maraCentre(p, params.planeSigma);
    float rotation = float(pcgHash(uint(p.x) + pcgHash(uint(p.y) + pcgHash(params.frame)))) * (1.0 / 4294967296.0);
    // Tap i's direction turns by a fixed angle from tap i - 1's: one rotation per tap
    // instead of a cos() and a sin() (it drifts from the formula by about one rounding
    // per tap: 1e-5 pixels after 50 taps of a 3-pixel radius).
    float inverseTaps = 1.0 / float(params.taps);
    float firstAngle = kTwoPi * (params.spiralTurns * 0.5 * inverseTaps + rotation);
    float stepAngle = kTwoPi * params.spiralTurns * inverseTaps;
    vec2 direction = vec2(cos(firstAngle), sin(firstAngle));
    mat2 turn = mat2(cos(stepAngle), sin(stepAngle), -sin(stepAngle), cos(stepAngle));
    ivec2 last = size - 1;
    vec3 sum = centre.rgb;
    float weightSum = 1.0;
    for (uint i = 0u; i < params.taps; ++i) {
        float a = (float(i) + 0.5) * inverseTaps;
        vec2 offset = r * a * direction;
        direction = turn * direction;
        ivec2 q = p + ivec2(floor(offset + 0.5));
        // Every tap is fetched (clamped) and weighed 0 where it does not count: no branch.
        bool counts = q != p && hushInside(q, size);
        q = clamp(q, ivec2(0), last);
        // |offset| = r a and sigma = r / 2: the Gaussian's exponent is 2 a^2 at any radius.
        float w = maraTapWeight(c, texelFetch(normal_depth, q, 0), texelFetch(position, q, 0).xyz, 2.0 * a * a,
                                params.normalPower, wholeNormalPower);
        w = counts ? w : 0.0;
        sum += w * texelFetch(color, q, 0).rgb;
        weightSum += w;
    }
    imageStore(filtered, p, vec4(sum / weightSum, centre.a));
}
