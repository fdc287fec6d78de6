#pragma once
// Command-line argument helpers shared by the `hush` subcommands and the benchmarks.
// Every failure is hush::Error (InvalidArgument) naming the option and the text given,
// never an exception from the standard library.
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace hush::core {

// Takes the value of an option given as "--name value" or "--name=value" at args[i]
// (advancing i past a separate value). False when args[i] is not that option.
bool takeOption(std::span<const std::string_view> args, size_t& i, std::string_view name, std::string& value);

// A whole number in [minimum, maximum].
uint32_t parseCount(std::string_view text, std::string_view option, uint32_t minimum,
                    uint32_t maximum = std::numeric_limits<uint32_t>::max());

// A finite number in [minimum, maximum].
double parseNumber(std::string_view text, std::string_view option, double minimum, double maximum);

// "640x360" (or "256" for 256x256 when `square` allows it); each side 1 .. maxSide.
struct Size2D {
    uint32_t width = 0;
    uint32_t height = 0;
};
Size2D parseSize(std::string_view text, std::string_view option, uint32_t maxSide = 16384, bool square = false);

// "a,b,,c" -> {"a", "b", "c"} (empty items dropped).
std::vector<std::string> splitList(std::string_view text, char separator = ',');

} // namespace hush::core
