// core/arguments: options with separate or attached values; numbers and sizes with
// errors that name the option and the text.
#include <catch2/catch.hpp>

#include <array>

#include <hush/core/arguments.hpp>
#include <hush/core/error.hpp>

using namespace hush;

TEST_CASE("arguments: takeOption reads --name value and --name=value", "[arguments]") {
    const std::array<std::string_view, 5> args{"--out", "dir", "--size=64x32", "--sizes", "--outer"};
    std::string value;
    size_t i = 0;
    REQUIRE(core::takeOption(args, i, "--out", value));
    CHECK(value == "dir");
    CHECK(i == 1);
    i = 2;
    REQUIRE(core::takeOption(args, i, "--size", value));
    CHECK(value == "64x32");
    i = 3;
    CHECK_FALSE(core::takeOption(args, i, "--size", value));   // "--sizes" is another option
    i = 4;
    CHECK_FALSE(core::takeOption(args, i, "--out", value));
    const std::array<std::string_view, 1> last{"--out"};
    i = 0;
    CHECK_THROWS_WITH(core::takeOption(last, i, "--out", value), "option --out needs a value");
}

TEST_CASE("arguments: counts, numbers and sizes are checked whole", "[arguments]") {
    CHECK(core::parseCount("12", "--frames", 1, 100) == 12u);
    CHECK_THROWS_WITH(core::parseCount("12x", "--frames", 1, 100), "--frames '12x' must be a whole number from 1 to 100");
    CHECK_THROWS_WITH(core::parseCount("0", "--frames", 1, 100), "--frames '0' must be a whole number from 1 to 100");
    CHECK_THROWS_AS(core::parseCount("-1", "--frames", 0), Error);
    CHECK(core::parseNumber("2.5", "--budget-ms", 0.0, 10.0) == 2.5);
    CHECK_THROWS_AS(core::parseNumber("nan", "--budget-ms", 0.0, 10.0), Error);
    const auto size = core::parseSize("640x360", "--size");
    CHECK(size.width == 640u);
    CHECK(size.height == 360u);
    CHECK(core::parseSize("64", "--size", 16384, true).height == 64u);
    CHECK_THROWS_WITH(core::parseSize("64", "--size"), "--size '64' is not a size like 640x360 (1 to 16384 each)");
    CHECK_THROWS_AS(core::parseSize("0x5", "--size"), Error);
    CHECK_THROWS_AS(core::parseSize("20000x5", "--size"), Error);
    CHECK(core::splitList("a,,b,c,") == std::vector<std::string>{"a", "b", "c"});
}
