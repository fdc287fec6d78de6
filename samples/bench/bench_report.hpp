#pragma once
// What every hush benchmark needs to report its figures: order statistics of
// repeated timings, the run's environment (core/run_environment.hpp) at the head of
// each results file, and result files written atomically (core/atomic_file.hpp).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <hush/core/arguments.hpp>
#include <hush/core/run_environment.hpp>

namespace hush::bench {

struct Stats {
    double median = 0.0;
    double min = 0.0;
    double max = 0.0;
};

// Median (mean of the two middle values for an even count), min and max.
// Throws hush::Error (InvalidArgument) for an empty sample.
Stats summarize(std::vector<double> samples);

// `text` as a JSON string literal, quotes included.
std::string jsonString(std::string_view text);
// A number with %.6g: enough digits for timings, no trailing noise.
std::string jsonNumber(double value);
// {"median": .., "min": .., "max": ..}
std::string statsJson(const Stats& s);

// The head of a results file: "{\n  \"environment\": {...},\n" (the caller adds
// its own fields and the closing brace).
std::string resultsHead(const core::RunEnvironment& environment);

// The program's arguments joined by spaces, for the results file.
std::string commandLineOf(int argc, char** argv);

// Creates the parent folder, then writes `contents` atomically.
void writeResults(const std::filesystem::path& path, std::string_view contents);

// Runs a benchmark's body and turns what it throws into the shared exit codes:
// 2 with "<program>: error (<kind>): ..." for a hush::Error, 2 with "internal
// error" for anything else; otherwise the body's own code.
int guardedMain(std::string_view program, const std::function<int()>& body);

} // namespace hush::bench
