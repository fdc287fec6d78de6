// Reporting helpers shared by the benchmarks (see bench_report.hpp).
#include "bench_report.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <system_error>

#include <unistd.h>

#include <hush/rhi/error.hpp>

namespace hush::bench {

Stats summarize(std::vector<double> samples) {
    if (samples.empty()) {
        throw Error(ErrorKind::InvalidArgument, "summarize: no samples (was --runs 0?)");
    }
    std::sort(samples.begin(), samples.end());
    size_t mid = samples.size() / 2;
    double median = samples.size() % 2 ? samples[mid] : 0.5 * (samples[mid - 1] + samples[mid]);
    return {.median = median, .min = samples.front(), .max = samples.back()};
}

std::string hostCpuName() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) == 0) {
            size_t colon = line.find(':');
            if (colon != std::string::npos && colon + 2 <= line.size()) {
                return line.substr(colon + 2);
            }
        }
    }
    return "unknown";
}

std::string utcTimestamp() {
    std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text;
}

std::string jsonString(std::string_view text) {
    std::string out = "\"";
    for (char c : text) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\t': out += "\\t"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                char escaped[8];
                std::snprintf(escaped, sizeof escaped, "\\u%04x", unsigned(c));
                out += escaped;
            } else {
                out += c;
            }
        }
    }
    return out + "\"";
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
    namespace fs = std::filesystem;
    std::error_code error;
    if (path.has_parent_path()) {
        fs::create_directories(path.parent_path(), error);
        if (error) {
            throw Error(ErrorKind::NotFound, "cannot create directory " + path.parent_path().string() + ": " +
                                                 error.message());
        }
    }
    // The process id keeps two concurrent runs from sharing a temporary file.
    fs::path temporary = path;
    temporary += ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(contents.data(), std::streamsize(contents.size()));
        out.close();
        if (!out) {
            fs::remove(temporary, error);
            throw Error(ErrorKind::NotFound, "cannot write " + temporary.string());
        }
    }
    fs::rename(temporary, path, error);
    if (error) {
        std::string reason = error.message();
        fs::remove(temporary, error);
        throw Error(ErrorKind::NotFound,
                    "cannot rename " + temporary.string() + " to " + path.string() + ": " + reason);
    }
}

} // namespace hush::bench

namespace hush::bench {

uint32_t parseCount(std::string_view flag, std::string_view text, uint32_t minimum) {
    uint32_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || value < minimum)
        throw hush::Error(hush::ErrorKind::InvalidArgument, std::string(flag) + " needs a whole number >= " +
                                                                std::to_string(minimum) + ", got '" + std::string(text) + "'");
    return value;
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
