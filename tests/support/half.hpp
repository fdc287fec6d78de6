#pragma once
// IEEE 754 binary16 <-> binary32 conversion, written for the tests so that expected
// values are derived independently of the GPU and of any library.
//
// halfToFloat is exact (every half is a float). floatToHalf rounds to nearest, ties
// to even, keeps subnormals, turns overflow into +-Inf and NaN into a quiet NaN that
// keeps the top payload bits.
#include <bit>
#include <cmath>
#include <cstdint>

namespace hush::test {

inline float halfToFloat(uint16_t h) {
    const uint32_t sign = uint32_t(h & 0x8000u) << 16;
    const uint32_t exponent = (h >> 10) & 0x1Fu;
    const uint32_t mantissa = h & 0x3FFu;
    if (exponent == 0) {
        // Zero or subnormal: mantissa * 2^-24, exact in float.
        const float magnitude = std::ldexp(float(mantissa), -24);
        return std::bit_cast<float>(sign | std::bit_cast<uint32_t>(magnitude));
    }
    if (exponent == 31) return std::bit_cast<float>(sign | 0x7F800000u | (mantissa << 13));
    return std::bit_cast<float>(sign | ((exponent - 15 + 127) << 23) | (mantissa << 13));
}

inline uint16_t floatToHalf(float value) {
    const uint32_t bits = std::bit_cast<uint32_t>(value);
    const uint16_t sign = uint16_t((bits >> 16) & 0x8000u);
    const uint32_t exponent = (bits >> 23) & 0xFFu;
    const uint32_t mantissa = bits & 0x7FFFFFu;
    if (exponent == 0xFF) return uint16_t(sign | 0x7C00u | (mantissa ? 0x200u | (mantissa >> 13) : 0u));

    // The half exponent this value would have as a normal number.
    const int halfExponent = int(exponent) - 127 + 15;
    if (halfExponent >= 31) return uint16_t(sign | 0x7C00u);
    // Significand with its implicit bit (float subnormals are far below half's range).
    const uint32_t significand = exponent == 0 ? mantissa : (mantissa | 0x800000u);
    // Bits to drop: 13 for a normal half, more for a subnormal one.
    const int shift = 13 + (halfExponent < 1 ? 1 - halfExponent : 0);
    if (shift > 24) return sign;   // below half the smallest subnormal: rounds to zero
    uint32_t q = significand >> shift;
    const uint32_t rest = significand & ((1u << shift) - 1u);
    const uint32_t halfway = 1u << (shift - 1);
    if (rest > halfway || (rest == halfway && (q & 1u))) ++q;
    if (halfExponent < 1) return uint16_t(sign | q);   // q == 0x400 is the smallest normal: still right
    // q is 0x400..0x800; 0x800 carries into the exponent (and to Inf at the top).
    return uint16_t(sign | ((uint32_t(halfExponent) << 10) + (q - 0x400u)));
}

} // namespace hush::test
