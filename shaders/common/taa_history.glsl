// TAA history resampling (passes/common/taa.hpp, TaaHistoryFilter): last frame's
// output at this pixel's previous position, bilinear or Catmull-Rom. The including
// shader declares `uniform texture2D history` and enables
// GL_EXT_samplerless_texture_functions.
//
// Positions are handled as p + m rather than p + 0.5 + m - 0.5: floor(p + m) =
// p + floor(m) and the fraction m - floor(m) are both exact in fp32, so the weights
// do not lose bits as the pixel coordinate grows (at x = 256 an fp32 position has
// 3e-5 px steps).
#ifndef HUSH_COMMON_TAA_HISTORY_GLSL
#define HUSH_COMMON_TAA_HISTORY_GLSL

const uint kTaaHistoryBilinear = 0u;
const uint kTaaHistoryCatmullRom = 1u;

vec3 taaHistoryTexel(ivec2 q, ivec2 size) {
    return texelFetch(history, clamp(q, ivec2(0), size - 1), 0).rgb;
}

// The Catmull-Rom spline's weights for the taps at -1, 0, 1, 2 around a position
// t in [0, 1) past tap 0: the cubic convolution kernel of Keys 1981 ("Cubic
// convolution interpolation for digital image processing") with a = -1/2, at the
// distances 1 + t, t, 1 - t, 2 - t, expanded and in Horner form. At t = 0 they are exactly (0, 1, 0, 0), so whole-pixel
// motion copies the history without any filtering.
vec4 catmullRomWeights(float t) {
    return vec4(t * (-0.5 + t * (1.0 - 0.5 * t)),
                1.0 + t * t * (-2.5 + 1.5 * t),
                t * (0.5 + t * (2.0 - 1.5 * t)),
                t * t * (-0.5 + 0.5 * t));
}

// False when the previous position p + 0.5 + m is off screen (or m is NaN): then
// there is no history. Edge texels repeat for taps beyond the border.
bool resampleTaaHistory(ivec2 p, vec2 m, ivec2 size, uint historyFilter, out vec3 colour) {
    colour = vec3(0.0);
    // 0 <= p + 0.5 + m < size, exact for sizes below 2^22. Checked before
    // ivec2(floor(m)), which would be undefined for a huge m.
    vec2 centre = vec2(p) + 0.5;
    if (!all(greaterThanEqual(m, -centre)) || !all(lessThan(m, vec2(size) - centre))) {
        return false;
    }
    vec2 whole = floor(m);
    vec2 f = m - whole;
    ivec2 i = p + ivec2(whole);
    if (historyFilter == kTaaHistoryCatmullRom) {
        // Separable: 4 taps along x per row, then the 4 rows along y.
        vec4 wx = catmullRomWeights(f.x);
        vec4 wy = catmullRomWeights(f.y);
        for (int j = 0; j < 4; ++j) {
            vec3 row = vec3(0.0);
            for (int k = 0; k < 4; ++k) {
                row += wx[k] * taaHistoryTexel(i + ivec2(k - 1, j - 1), size);
            }
            colour += wy[j] * row;
        }
        return true;
    }
    vec3 top = mix(taaHistoryTexel(i, size), taaHistoryTexel(i + ivec2(1, 0), size), f.x);
    vec3 bottom = mix(taaHistoryTexel(i + ivec2(0, 1), size), taaHistoryTexel(i + ivec2(1, 1), size), f.x);
    colour = mix(top, bottom, f.y);
    return true;
}

#endif
