#include <hush/core/run_environment.hpp>

#include <algorithm>
#include <ctime>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

namespace hush::core {

std::string_view hushVersion() { return HUSH_VERSION; }

std::string hostCpuName() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) != 0) continue;
        const size_t colon = line.find(':');
        if (colon != std::string::npos && colon + 2 <= line.size()) return line.substr(colon + 2);
    }
    return "unknown";
}

std::string utcTimestamp() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text;
}

uint64_t availableHostMemory() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    uint64_t kib = 0;
    std::string unit;
    while (meminfo >> key >> kib >> unit)
        if (key == "MemAvailable:") return kib * 1024;
    return 0;
}

CpuTimes sampleCpuTimes() {
    CpuTimes t;
    std::ifstream stat("/proc/stat");
    std::string label;
    if (stat >> label && label == "cpu") {
        // user nice system idle iowait irq softirq steal (guest time is inside user)
        uint64_t field[8] = {};
        for (auto& f : field) stat >> f;
        for (uint64_t f : field) t.hostTotal += f;
        t.hostBusy = t.hostTotal - field[3] - field[4];
    }
    // Fields 14 and 15 of /proc/self/stat: utime and stime of every thread (a CPU
    // device's included). Field 2, the command name, is in parentheses and may hold spaces.
    std::ifstream self("/proc/self/stat");
    std::string text((std::istreambuf_iterator<char>(self)), std::istreambuf_iterator<char>());
    const size_t close = text.rfind(')');
    if (close == std::string::npos) return t;
    std::istringstream rest(text.substr(close + 2));
    std::string skip;
    for (int field = 3; field < 14; ++field) rest >> skip;
    uint64_t utime = 0, stime = 0;
    if (rest >> utime >> stime) t.self = utime + stime;
    return t;
}

double otherCpuShare(const CpuTimes& before, const CpuTimes& after) {
    if (after.hostTotal <= before.hostTotal || after.self < before.self) return -1.0;
    const double others = double(after.hostBusy - before.hostBusy) - double(after.self - before.self);
    return std::clamp(others / double(after.hostTotal - before.hostTotal), 0.0, 1.0);
}

nlohmann::ordered_json toJson(const RunEnvironment& e) {
    nlohmann::ordered_json device = nlohmann::ordered_json::object();
    for (const auto& [key, value] : e.device) device[key] = value;
    nlohmann::ordered_json json;
    json["program"] = e.program;
    json["date"] = utcTimestamp();
    json["hush_version"] = std::string(hushVersion());
    json["command_line"] = e.commandLine;
    json["host"] = {{"cpu", hostCpuName()}, {"hardware_threads", std::thread::hardware_concurrency()}};
    json["device"] = device;
    json["validation"] = e.validation;
    return json;
}

} // namespace hush::core
