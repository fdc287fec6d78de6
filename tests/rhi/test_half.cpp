// The tests' own fp16 conversion (support/half.hpp), checked against values derived
// by hand from IEEE 754 binary16 (sign 1, exponent 5 with bias 15, mantissa 10), so
// the format tests can trust the bit patterns they build with it. CPU only.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "support/half.hpp"

using hush::test::floatToHalf;
using hush::test::halfToFloat;

TEST_CASE("half: decodes the edge values of binary16", "[half]") {
    CHECK(halfToFloat(0x0000) == 0.0f);
    CHECK(std::signbit(halfToFloat(0x8000)));
    CHECK(halfToFloat(0x3C00) == 1.0f);
    CHECK(halfToFloat(0xC000) == -2.0f);
    CHECK(halfToFloat(0x3555) == 0.333251953125f);             // 1.0101010101b * 2^-2
    CHECK(halfToFloat(0x7BFF) == 65504.0f);                    // max: (2 - 2^-10) * 2^15
    CHECK(halfToFloat(0xFBFF) == -65504.0f);
    CHECK(halfToFloat(0x0400) == std::ldexp(1.0f, -14));       // smallest normal
    CHECK(halfToFloat(0x0001) == std::ldexp(1.0f, -24));       // smallest subnormal
    CHECK(halfToFloat(0x0200) == std::ldexp(1.0f, -15));       // a subnormal: 512 * 2^-24
    CHECK(halfToFloat(0x03FF) == std::ldexp(1023.0f, -24));    // largest subnormal
    CHECK(halfToFloat(0x7C00) == std::numeric_limits<float>::infinity());
    CHECK(halfToFloat(0xFC00) == -std::numeric_limits<float>::infinity());
    CHECK(std::isnan(halfToFloat(0x7E00)));
    CHECK(std::isnan(halfToFloat(0x7C01)));
}

TEST_CASE("half: encodes with round to nearest even", "[half]") {
    CHECK(floatToHalf(0.0f) == 0x0000);
    CHECK(floatToHalf(-0.0f) == 0x8000);
    CHECK(floatToHalf(1.0f) == 0x3C00);
    CHECK(floatToHalf(65504.0f) == 0x7BFF);
    CHECK(floatToHalf(-65504.0f) == 0xFBFF);
    CHECK(floatToHalf(65519.0f) == 0x7BFF);                    // below the halfway point to 2^16
    CHECK(floatToHalf(65520.0f) == 0x7C00);                    // halfway, ties to even: overflows to Inf
    CHECK(floatToHalf(1e6f) == 0x7C00);
    CHECK(floatToHalf(-1e6f) == 0xFC00);
    CHECK(floatToHalf(std::ldexp(1.0f, -24)) == 0x0001);
    CHECK(floatToHalf(std::ldexp(1.0f, -15)) == 0x0200);
    CHECK(floatToHalf(std::ldexp(1.0f, -14)) == 0x0400);
    CHECK(floatToHalf(std::ldexp(1.0f, -25)) == 0x0000);       // half the smallest subnormal: tie to 0
    CHECK(floatToHalf(std::ldexp(1.5f, -25)) == 0x0001);
    CHECK(floatToHalf(std::ldexp(3.0f, -25)) == 0x0002);       // 1.5 subnormal steps: tie to even 2
    CHECK(floatToHalf(std::ldexp(1023.5f, -24)) == 0x0400);    // rounds up out of the subnormals
    CHECK(floatToHalf(1.0f + std::ldexp(1.0f, -11)) == 0x3C00); // halfway between 1 and next: even
    CHECK(floatToHalf(1.0f + std::ldexp(3.0f, -11)) == 0x3C02); // halfway, odd below: up
    CHECK(floatToHalf(std::numeric_limits<float>::infinity()) == 0x7C00);
    CHECK(floatToHalf(std::numeric_limits<float>::denorm_min()) == 0x0000);
    const uint16_t nan = floatToHalf(std::numeric_limits<float>::quiet_NaN());
    CHECK((nan & 0x7C00) == 0x7C00);
    CHECK((nan & 0x03FF) != 0);
}

TEST_CASE("half: every non-NaN binary16 survives float and back", "[half]") {
    int mismatches = 0;
    for (uint32_t h = 0; h <= 0xFFFF; ++h) {
        const float f = halfToFloat(uint16_t(h));
        if (std::isnan(f)) {
            // NaN stays NaN (quiet) with the same sign.
            const uint16_t back = floatToHalf(f);
            if ((back & 0x7C00) != 0x7C00 || (back & 0x3FF) == 0 || (back & 0x8000) != (h & 0x8000)) ++mismatches;
        } else if (floatToHalf(f) != h) {
            ++mismatches;
        }
    }
    CHECK(mismatches == 0);
}
