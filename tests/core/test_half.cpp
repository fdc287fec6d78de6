// core::halfToFloat / floatToHalf (Imath's conversion) against the tests' own
// independent binary16 code (support/half.hpp), over every half bit pattern and
// floats around each rounding boundary.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>

#include <hush/core/half.hpp>

#include "support/half.hpp"

TEST_CASE("core half: every half decodes as the tests' decoder says", "[core][half]") {
    for (uint32_t h = 0; h <= 0xFFFFu; ++h) {
        const float ours = hush::core::halfToFloat(uint16_t(h)), theirs = hush::test::halfToFloat(uint16_t(h));
        if (std::isnan(theirs)) {
            REQUIRE(std::isnan(ours));
            continue;
        }
        REQUIRE(std::bit_cast<uint32_t>(ours) == std::bit_cast<uint32_t>(theirs));
    }
}

TEST_CASE("core half: encoding rounds as the tests' encoder does", "[core][half]") {
    for (uint32_t h = 0; h < 0x7C00u; ++h) {   // every finite non-negative half, and the floats around it
        const float f = hush::test::halfToFloat(uint16_t(h));
        for (const float v : {f, std::nextafter(f, 0.0f), std::nextafter(f, 1e9f), f * 1.00048828125f}) {
            INFO("value " << v);
            REQUIRE(hush::core::floatToHalf(v) == hush::test::floatToHalf(v));
            REQUIRE(hush::core::floatToHalf(-v) == hush::test::floatToHalf(-v));
        }
    }
    REQUIRE(hush::core::floatToHalf(1e6f) == 0x7C00u);
}
