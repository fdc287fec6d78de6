#pragma once
// Random numbers and sample warps for the path tracer. Everything is a pure
// function of (seed, pixel, frame, sample, dimension), so renders are deterministic
// for a given seed whatever the thread count.
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

namespace hush::tracer::detail {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

// A 32-bit integer hash with good avalanche (a "lowbias32"-style mixer).
inline uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}
inline uint32_t hashCombine(uint32_t a, uint32_t b) { return hash32(a ^ (b + 0x9e3779b9U + (a << 6) + (a >> 2))); }

// The radical inverse of `index` in prime base `base` (the Halton sequence).
float radicalInverse(uint32_t base, uint64_t index);

// Low-discrepancy samples for one pixel: the Halton sequence over dimensions, each
// dimension shifted by a per-pixel, per-dimension random offset (Cranley-Patterson
// rotation), so neighbouring pixels decorrelate while each pixel's sequence keeps its
// stratification over frames and over the reference's samples. Dimensions past the
// table of primes fall back to hashed random numbers.
class PixelSampler {
public:
    PixelSampler(uint32_t seed, uint32_t x, uint32_t y, uint64_t sampleIndex)
        : pixelKey_(hashCombine(hashCombine(seed, x), y)), index_(sampleIndex) {}
    float next();
    glm::vec2 next2() {
        const float a = next();
        return {a, next()};
    }

private:
    uint32_t pixelKey_;
    uint64_t index_;
    uint32_t dimension_ = 0;
};

// Warps from [0,1)^2.
glm::vec3 sampleCosineHemisphere(glm::vec2 u);                        // z-up, pdf = cos / pi
glm::vec3 sampleUniformCone(glm::vec2 u, float cosMax);               // z-up, pdf = 1 / (2 pi (1 - cosMax))
glm::vec2 sampleUniformTriangle(glm::vec2 u);                         // barycentrics (b1, b2)

// An orthonormal basis around n (Duff et al. 2017's branchless construction).
struct Basis {
    glm::vec3 t, b, n;
    explicit Basis(glm::vec3 normal);
    glm::vec3 toLocal(glm::vec3 v) const { return {glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)}; }
    glm::vec3 toWorld(glm::vec3 v) const { return v.x * t + v.y * b + v.z * n; }
};

inline float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

} // namespace hush::tracer::detail
