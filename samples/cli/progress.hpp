#pragma once
// A progress line for long work: a bar, the percentage and the time left. On a
// terminal it redraws in place; in a log (not a tty) it prints at most every few
// seconds, so CI output stays readable.
#include <chrono>
#include <cstdint>
#include <string>

namespace hush::cli {

class ProgressLine {
public:
    explicit ProgressLine(std::string label);
    // `done` of `total` units; `detail` is appended (e.g. "frame 3/60").
    void update(double fraction, const std::string& detail);
    void finish(const std::string& summary);

private:
    std::string label_;
    std::chrono::steady_clock::time_point start_, lastPrint_;
    bool tty_;
    bool printed_ = false;
};

std::string formatSeconds(double seconds);

} // namespace hush::cli
