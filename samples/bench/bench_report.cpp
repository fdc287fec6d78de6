// Reporting helpers shared by the benchmarks (see bench_report.hpp).
#include "bench_report.hpp"

#include <algorithm>
#include <cstdio>

#include <hush/core/atomic_file.hpp>
#include <hush/core/error.hpp>
#include <hush/core/json.hpp>

namespace hush::bench {

Stats summarize(std::vector<double> samples) {
    if (samples.empty()) throw Error(ErrorKind::InvalidArgument, "summarize: no samples (was --runs 0?)");
    std::sort(samples.begin(), samples.end());
    const size_t mid = samples.size() / 2;
    const double median = samples.size() % 2 ? samples[mid] : 0.5 * (samples[mid - 1] + samples[mid]);
    return {.median = median, .min = samples.front(), .max = samples.back()};
}

std::string jsonString(std::string_view text) { return core::Json(std::string(text)).dump(); }

std::string jsonNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

std::string statsJson(const Stats& s) {
    return "{\"median\": " + jsonNumber(s.median) + ", \"min\": " + jsonNumber(s.min) + ", \"max\": " +
           jsonNumber(s.max) + "}";
}

std::string resultsHead(const core::RunEnvironment& environment) {
    return "{\n  \"environment\": " + core::toJson(environment).dump() + ",\n";
}

std::string commandLineOf(int argc, char** argv) {
    std::string line;
    for (int i = 0; i < argc; ++i) line += (i ? " " : "") + std::string(argv[i]);
    return line;
}

void writeResults(const std::filesystem::path& path, std::string_view contents) {
    std::error_code error;
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), error);
    if (error)
        throw Error(ErrorKind::Io, "cannot create the folder '" + path.parent_path().string() + "': " + error.message());
    core::writeFileAtomically(path, contents);
}

int guardedMain(std::string_view program, const std::function<int()>& body) {
    try {
        return body();
    } catch (const hush::Error& error) {
        std::fflush(stdout);
        std::fprintf(stderr, "%.*s: error (%s): %s\n", int(program.size()), program.data(), hush::toString(error.kind()),
                     error.what());
        return 2;
    } catch (const std::exception& error) {
        std::fflush(stdout);
        std::fprintf(stderr, "%.*s: internal error: %s\n", int(program.size()), program.data(), error.what());
        return 2;
    }
}

} // namespace hush::bench
