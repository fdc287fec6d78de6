#pragma once
// What every hush benchmark needs to report its figures: order statistics of
// repeated timings, a description of the machine, and result files written so
// that an interrupted run never leaves a half-written one behind.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace hush::bench {

struct Stats {
    double median = 0.0;
    double min = 0.0;
    double max = 0.0;
};

// Median (mean of the two middle values for an even count), min and max.
// Throws hush::Error (InvalidArgument) for an empty sample.
Stats summarize(std::vector<double> samples);

// The CPU's model name from /proc/cpuinfo ("unknown" when unavailable).
std::string hostCpuName();

// Now, in UTC, as ISO 8601: "2024-05-01T12:34:56Z".
std::string utcTimestamp();

// `text` as a JSON string literal, quotes included.
std::string jsonString(std::string_view text);

// Writes `contents` to a temporary file beside `path`, then renames it over
// `path` (atomic on one file system). Creates the parent directory. Throws
// hush::Error (NotFound) naming the path when it cannot.
void writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

// A command-line count: the whole text a number >= minimum, else hush::Error
// (InvalidArgument) naming the flag and the text.
uint32_t parseCount(std::string_view flag, std::string_view text, uint32_t minimum);

// Runs a benchmark's body and turns what it throws into the shared exit codes:
// 2 with "<program>: error (<kind>): ..." for a hush::Error, 2 with "internal
// error" for anything else; otherwise the body's own code.
int guardedMain(std::string_view program, const std::function<int()>& body);

} // namespace hush::bench
