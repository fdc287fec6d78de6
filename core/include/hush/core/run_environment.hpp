#pragma once
// What every results file (benchmarks, `hush demo`'s report, sweeps) records about the
// run that made it, so that figures are only compared with figures from like runs:
// when, which hush, which command, which CPU and how busy the rest of the machine was,
// which device and driver.
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <hush/core/json.hpp>

namespace hush::core {

// The project version ("0.1.0").
std::string_view hushVersion();
// The CPU's model name from /proc/cpuinfo ("unknown" when unavailable).
std::string hostCpuName();
// Now, in UTC, as ISO 8601: "2026-12-02T12:34:56Z".
std::string utcTimestamp();
// Host memory a new allocation can still get (MemAvailable in /proc/meminfo), in
// bytes; 0 when unknown. For refusing, before allocating, work that cannot fit.
uint64_t availableHostMemory();

// CPU time counters (clock ticks) of the whole host and of this process, from
// /proc/stat and /proc/self/stat; all zero where unavailable.
struct CpuTimes {
    uint64_t hostBusy = 0, hostTotal = 0, self = 0;
};
CpuTimes sampleCpuTimes();
// Other processes' share of the host's CPU time between two samples, in [0, 1]; -1
// when unknown. On a CPU device (lavapipe) the "GPU" is the host's cores, so a
// timing taken while others ran is not comparable.
double otherCpuShare(const CpuTimes& before, const CpuTimes& after);

struct RunEnvironment {
    std::string program;                 // "chains", "bandwidth", "demo"
    std::string commandLine;
    // The device: name, type, driver, ... as the program's GPU layer describes it.
    std::vector<std::pair<std::string, std::string>> device;
    bool validation = false;             // Vulkan validation layers were on (timings are then not representative)
};

// The record as an ordered JSON object: program, date, hush_version, command_line,
// host {cpu, hardware_threads}, device {...}, validation.
nlohmann::ordered_json toJson(const RunEnvironment& environment);

} // namespace hush::core
