// Reading a history texture through the decision made by common/reproject.comp
// (encoding in passes/include/hush/passes/common/reproject.hpp):
//   decision.xy  floor = top-left tap; in mode 1 the fraction is the bilinear position
//   decision.z   bitmask of usable taps, bit (j * width + i)
//   decision.w   0 disoccluded, 1 bilinear 2x2, 2 3x3 with equal weights
// Bilinear weights of rejected taps are redistributed by renormalising over the
// usable ones (SVGF Sec. 4.1); the 3x3 fallback weighs its usable taps equally.
// Needs GL_EXT_samplerless_texture_functions in the including shader.
#ifndef HUSH_COMMON_REPROJECTION_GLSL
#define HUSH_COMMON_REPROJECTION_GLSL

const uint kReprojectDisoccluded = 0u;
const uint kReprojectBilinear = 1u;
const uint kReprojectFallback3x3 = 2u;

// The taps of one pixel's history footprint and their normalised weights
// (0 for the taps not to be used). width is 2 or 3; tap (i, j) is at origin + (i, j)
// and its weight is weight[j * 3 + i] whatever the width (the decision's mask bit is
// j * width + i). The fixed layout and constant loop bounds let compilers unroll the
// loops and keep the weights in registers.
struct ReprojectionFootprint {
    ivec2 origin;
    int width;
    float weight[9];
};

// False (and a zero-weight footprint) where the decision says disoccluded, or it
// holds no usable tap.
bool reprojectionFootprint(vec4 decision, out ReprojectionFootprint f) {
    uint mode = uint(decision.w + 0.5);
    uint mask = uint(decision.z + 0.5);
    vec2 base = floor(decision.xy);
    f.origin = ivec2(0);
    f.width = 2;
    for (int k = 0; k < 9; ++k) {
        f.weight[k] = 0.0;
    }
    if (mode == kReprojectDisoccluded || mode > kReprojectFallback3x3 || mask == 0u) {
        return false;
    }
    f.origin = ivec2(base);
    f.width = mode == kReprojectBilinear ? 2 : 3;
    vec2 frac = decision.xy - base;
    float sum = 0.0;
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
            if (i >= f.width || j >= f.width || (mask & (1u << uint(j * f.width + i))) == 0u) {
                continue;
            }
            float w = 1.0;
            if (mode == kReprojectBilinear) {
                w = (i == 0 ? 1.0 - frac.x : frac.x) * (j == 0 ? 1.0 - frac.y : frac.y);
            }
            f.weight[j * 3 + i] = w;
            sum += w;
        }
    }
    // The reprojection pass sets only taps of positive weight, so sum > 0; should a
    // decision say otherwise, its usable taps are weighed equally rather than by 0/0.
    if (!(sum > 0.0)) {
        sum = 0.0;
        for (int j = 0; j < 3; ++j) {
            for (int i = 0; i < 3; ++i) {
                bool usable = i < f.width && j < f.width && (mask & (1u << uint(j * f.width + i))) != 0u;
                f.weight[j * 3 + i] = usable ? 1.0 : 0.0;
                sum += f.weight[j * 3 + i];
            }
        }
    }
    for (int k = 0; k < 9; ++k) {
        f.weight[k] /= sum;
    }
    return true;
}

// The weighted sum of `history` over the footprint's usable taps.
vec4 fetchFootprint(texture2D history, ReprojectionFootprint f) {
    vec4 value = vec4(0.0);
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
            float w = f.weight[j * 3 + i];
            if (w > 0.0) {
                value += w * texelFetch(history, f.origin + ivec2(i, j), 0);
            }
        }
    }
    return value;
}

// fetchFootprint of a footprint of width 2 (its weights past the 2x2 are 0): the
// same sum in the same order, from 4 fetches instead of 9.
vec4 fetchFootprint2x2(texture2D history, ReprojectionFootprint f) {
    vec4 value = vec4(0.0);
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            float w = f.weight[j * 3 + i];
            if (w > 0.0) {
                value += w * texelFetch(history, f.origin + ivec2(i, j), 0);
            }
        }
    }
    return value;
}

// One history value through a decision: false where disoccluded (value = 0).
bool fetchReprojected(texture2D history, vec4 decision, out vec4 value) {
    ReprojectionFootprint f;
    bool ok = reprojectionFootprint(decision, f);
    value = ok ? fetchFootprint(history, f) : vec4(0.0);
    return ok;
}

#endif
