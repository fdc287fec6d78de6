// passes/common/normal_power: which exponents the shaders evaluate by repeated squaring.
// The GPU results of both paths are compared with std::pow in the CPU reference tests of
// svgf.atrous, svgf.variance and the Mara bilaterals.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <hush/passes/common/normal_power.hpp>

using namespace hush;

TEST_CASE("normal power: whole exponents in 1..65535 are squared, every other value uses pow", "[common][normal-power]") {
    CHECK(passes::wholeExponent(1.0f) == 1);
    CHECK(passes::wholeExponent(32.0f) == 32);
    CHECK(passes::wholeExponent(128.0f) == 128);
    CHECK(passes::wholeExponent(65535.0f) == 65535);
    for (float notWhole : {0.0f, 0.5f, 127.5f, 65536.0f, 1e30f, -2.0f, std::numeric_limits<float>::infinity(),
                           std::numeric_limits<float>::quiet_NaN()})
        CHECK(passes::wholeExponent(notWhole) == 0);
    const auto constant = passes::normalPowerConstant("wholeSigmaN", 128.0f);
    CHECK(constant.key == "wholeSigmaN");
    CHECK(constant.value == 128.0);
}
