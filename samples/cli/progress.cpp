#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace hush::cli {

std::string formatSeconds(double seconds) {
    char text[32];
    if (seconds < 60.0) std::snprintf(text, sizeof text, "%.1f s", seconds);
    else std::snprintf(text, sizeof text, "%dm%02ds", int(seconds) / 60, int(seconds) % 60);
    return text;
}

ProgressLine::ProgressLine(std::string label)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()), lastPrint_(start_),
      tty_(isatty(fileno(stderr)) != 0) {}

void ProgressLine::update(double fraction, const std::string& detail) {
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double sinceLast = std::chrono::duration<double>(now - lastPrint_).count();
    if (tty_ ? sinceLast < 0.1 : sinceLast < 5.0) return;   // redraw at 10 Hz, log every 5 s
    lastPrint_ = now;
    fraction = std::clamp(fraction, 0.0, 1.0);
    const int width = 30, filled = int(fraction * width + 0.5);
    const std::string bar = std::string(size_t(filled), '#') + std::string(size_t(width - filled), '.');
    const std::string eta = fraction > 0.01 ? formatSeconds(elapsed * (1.0 - fraction) / fraction) + " left" : "...";
    std::fprintf(stderr, "%s%s [%s] %3.0f%%  %s  %s%s", tty_ ? "\r" : "", label_.c_str(), bar.c_str(), fraction * 100.0,
                 detail.c_str(), eta.c_str(), tty_ ? "\033[K" : "\n");
    std::fflush(stderr);
    printed_ = true;
}

void ProgressLine::finish(const std::string& summary) {
    std::fprintf(stderr, "%s%s %s%s\n", tty_ && printed_ ? "\r" : "", label_.c_str(), summary.c_str(), tty_ ? "\033[K" : "");
    std::fflush(stderr);
}

} // namespace hush::cli
