// Mara et al. 2017's temporal stages (seed 000 Sec. 3.4, Eq. 11), shared by the matte
// (3) and glossy (8) ones, which differ only in where last frame's sample is: the
// matte one follows the motion vector, the glossy one projects the virtual
// (reflected) position with last frame's camera.
//   c = h * (1 - smoothstep(d0, d1, |X_expected - X_actual| in metres))
//   out = mix(x, clamp(history, min3x3(x), max3x3(x)), h * c),   out.a = c
// The paper prints smoothstep(d0, d1, d) itself; that would trust history only when
// the positions differ by more than 7 cm, the opposite of "a smooth transition at 6 cm
// from 0 to 95% hysteresis" (h * c ranges over [0, h^2] = [0, 0.96]): the decreasing
// form is the one the text describes (docs/passes/mara.md).
// The including shader declares: `history`, `position_history` (texture2D), the
// current signal `x` as texture2D `current`, the output image `temporal`, and the
// push constants hysteresis, d0, d1, metresPerUnit, historyValid.
#ifndef HUSH_MARA_TEMPORAL_GLSL
#define HUSH_MARA_TEMPORAL_GLSL

float maraConfidence(float hysteresis, float d0, float d1, float distanceMetres) {
    float t = clamp((distanceMetres - d0) / max(d1 - d0, 1e-12), 0.0, 1.0);
    return hysteresis * (1.0 - t * t * (3.0 - 2.0 * t));
}

// Bilinear fetch of last frame's colour and position at pixel position q (pixel
// centres at +0.5), over the taps inside the image, renormalised. False when no tap is.
bool maraFetchHistory(vec2 q, ivec2 size, out vec3 color, out vec3 position) {
    vec2 base = floor(q - 0.5);
    vec2 f = q - 0.5 - base;
    color = vec3(0.0);
    position = vec3(0.0);
    float sum = 0.0;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            ivec2 t = ivec2(base) + ivec2(i, j);
            if (!hushInside(t, size)) {
                continue;
            }
            float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
            color += w * texelFetch(history, t, 0).rgb;
            position += w * texelFetch(position_history, t, 0).xyz;
            sum += w;
        }
    }
    if (!(sum > 0.0)) {
        return false;
    }
    color /= sum;
    position /= sum;
    return true;
}

// The temporal blend at pixel p whose last-frame position is q (in pixels; any value
// when `reprojected` is false), with X_expected = `expected`.
vec4 maraTemporal(ivec2 p, ivec2 size, vec2 q, bool reprojected, vec3 expected, float hysteresis, float d0, float d1,
                  float metresPerUnit) {
    vec3 x = texelFetch(current, p, 0).rgb;
    vec3 lo = x;
    vec3 hi = x;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            vec3 n = texelFetch(current, clamp(p + ivec2(dx, dy), ivec2(0), size - 1), 0).rgb;
            lo = min(lo, n);
            hi = max(hi, n);
        }
    }
    vec3 color;
    vec3 actual;
    if (!reprojected || !maraFetchHistory(q, size, color, actual)) {
        return vec4(x, 0.0);
    }
    float c = maraConfidence(hysteresis, d0, d1, distance(expected, actual) * metresPerUnit);
    return vec4(mix(x, clamp(color, lo, hi), hysteresis * c), c);
}

#endif
