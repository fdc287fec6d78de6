#include "sampling.hpp"

#include <algorithm>
#include <array>
#include <iterator>
#include <utility>

namespace hush::tracer::detail {

namespace {
constexpr uint32_t kPrimes[] = {2,  3,  5,  7,  11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53,
                                59, 61, 67, 71, 73, 79, 83, 89, 97, 101, 103, 107, 109, 113, 127, 131};

// Inlined into a caller with a constant base, the divisions become multiplications
// (the variable-base loop's 64-bit divisions were most of the sampler's time); the
// arithmetic, and so every sample, is the same.
[[gnu::always_inline]] inline float radicalInverseLoop(uint32_t base, uint64_t index) {
    const double inverseBase = 1.0 / base;
    double factor = inverseBase, value = 0.0;
    while (index > 0) {
        const uint64_t next = index / base;
        value += double(index - next * base) * factor;
        factor *= inverseBase;
        index = next;
    }
    return std::min(float(value), kOneMinusEpsilon);
}

template <uint32_t Base>
float radicalInverseIn(uint64_t index) {
    return radicalInverseLoop(Base, index);
}

using RadicalInverseFn = float (*)(uint64_t);

template <size_t... I>
constexpr std::array<RadicalInverseFn, sizeof...(I)> radicalInverseTable(std::index_sequence<I...>) {
    return {&radicalInverseIn<kPrimes[I]>...};
}
constexpr auto kRadicalInverse = radicalInverseTable(std::make_index_sequence<std::size(kPrimes)>());

} // namespace

float radicalInverse(uint32_t base, uint64_t index) { return radicalInverseLoop(base, index); }

float PixelSampler::next() {
    const uint32_t d = dimension_++;
    const uint32_t key = hashCombine(pixelKey_, d);
    const float offset = float(key >> 8) * 0x1p-24f;
    if (d < std::size(kPrimes)) {
        float v = kRadicalInverse[d](index_) + offset;
        v -= std::floor(v);
        return std::min(v, kOneMinusEpsilon);
    }
    const uint32_t r = hashCombine(key, uint32_t(index_) ^ uint32_t(index_ >> 32));
    return float(r >> 8) * 0x1p-24f;
}

glm::vec3 sampleCosineHemisphere(glm::vec2 u) {
    const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x))};
}

glm::vec3 sampleUniformCone(glm::vec2 u, float cosMax) {
    const float cosTheta = 1.0f - u.x * (1.0f - cosMax);
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    const float phi = 2.0f * kPi * u.y;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

glm::vec2 sampleUniformTriangle(glm::vec2 u) {
    const float s = std::sqrt(u.x);
    return {1.0f - s, u.y * s};
}

Basis::Basis(glm::vec3 normal) : n(normal) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b2 = n.x * n.y * a;
    t = {1.0f + sign * n.x * n.x * a, sign * b2, -sign * n.x};
    b = {b2, sign + n.y * n.y * a, -n.y};
}

} // namespace hush::tracer::detail
