// BMFR feature buffers (Koskela et al. 2019, Sec. 5, Eq. 7) and the stochastic
// regularisation noise (Sec. 3.2), shared by the fit kernel. The codes match
// hush::passes::BmfrFeature; the hash must match the CPU reference's
// (tests/passes/reference/bmfr_fit.cpp) bit for bit.
#ifndef HUSH_BMFR_FEATURES_GLSL
#define HUSH_BMFR_FEATURES_GLSL

const uint kBmfrOne = 0u;
const uint kBmfrPositionX2 = 7u;
const uint kBmfrBlockU = 15u;
const uint kBmfrBlockV = 16u;

// Everything a pixel's features are made of, fetched once.
struct BmfrGuideTexel {
    vec3 normal;
    vec3 position;
    vec3 albedo;
    float roughness;
    float meshId;
    vec2 inBlock;   // position in the block, 0 .. 1
};

// The raw (unscaled) value of feature `code`. Squares saturate at 3e38 rather than
// overflowing to Inf.
float bmfrRawFeature(uint code, BmfrGuideTexel g) {
    if (code == kBmfrOne) return 1.0;
    if (code <= 3u) return g.normal[code - 1u];
    if (code <= 6u) return g.position[code - 4u];
    if (code <= 9u) {
        float w = g.position[code - kBmfrPositionX2];
        return min(w * w, 3.0e38);
    }
    if (code <= 12u) return g.albedo[code - 10u];
    if (code == 13u) return g.roughness;
    if (code == 14u) return g.meshId;
    if (code == kBmfrBlockU) return g.inBlock.x;
    return g.inBlock.y;
}

// Scaled to [-1, 1] over the block (Sec. 3.2): 2 (f - lo) / (hi - lo) - 1, computed
// with halves so that a range near the float maximum cannot overflow. halfRange 0
// marks a feature that is constant in the block: its column is 0 (the One column
// already carries constants). The One column itself is 1.
float bmfrScaled(uint code, float f, float lo, float halfRange) {
    if (code == kBmfrOne) return 1.0;
    if (!(halfRange > 0.0)) return 0.0;
    return clamp((f * 0.5 - lo * 0.5) / halfRange - 1.0, -1.0, 1.0);
}

// Integer mixing: xor-shift / multiply by the 32-bit golden-ratio constant.
uint bmfrMix(uint h) {
    h ^= h >> 16;
    h *= 0x9E3779B9u;
    h ^= h >> 13;
    h *= 0x9E3779B9u;
    h ^= h >> 16;
    return h;
}

// N(p, column) uniform in [-epsilon, epsilon) (Sec. 3.2), a deterministic function of
// the pixel, the frame and the column, so that the CPU reference draws the same N.
float bmfrNoise(uvec2 pixel, uint frame, uint column, float epsilon) {
    uint h = bmfrMix(pixel.x ^ bmfrMix(pixel.y ^ bmfrMix(frame ^ bmfrMix(column))));
    return epsilon * (float(h >> 8) * (2.0 / 16777216.0) - 1.0);
}

#endif
