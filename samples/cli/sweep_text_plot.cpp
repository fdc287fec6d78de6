// The sweep's plot as text, for a terminal and for Markdown (docs embed it; the PNG
// and SVG are benchmark outputs, not committed): GPU ms across, the metric up (better
// is up), each configuration a letter of the table's order, uppercase on the front,
// '+' where several share a cell, the noisy input's quality as a row of '-'.
#include <algorithm>
#include <cstdio>

#include "sweep_result.hpp"

namespace hush::cli {
namespace {

// Past the 26th configuration letters would repeat and the key would lie: those are '*'.
char letterOf(size_t index, bool onFront) {
    if (index >= 26) return '*';
    const char base = char('a' + index);
    return onFront ? char(base - 'a' + 'A') : base;
}

} // namespace

std::string sweepTextPlot(const SweepResult& r, const SweepSource& s, int columns, int rows) {
    const auto& metric = sweepMetric(r.metric);
    const auto points = r.pointsOf(s.key);
    const auto front = paretoFront(points, metric);
    const double noisy = metric.of(s.noisy);
    const SweepExtent extent = sweepExtent(points, metric, noisy);
    double xHi = extent.msHi > 0 ? extent.msHi : 1.0, yLo = extent.lo, yHi = extent.hi;
    if (!(yHi > yLo)) yLo -= 0.5, yHi += 0.5;
    // Better is up: the top row is the best value.
    auto rowOf = [&](double v) {
        const double t = (v - yLo) / (yHi - yLo);
        return int((metric.higherIsBetter ? 1.0 - t : t) * (rows - 1) + 0.5);
    };
    auto columnOf = [&](double ms) { return int(ms / xHi * (columns - 1) + 0.5); };
    std::vector<std::string> grid(size_t(rows), std::string(size_t(columns), ' '));
    auto& noisyRow = grid[size_t(rowOf(noisy))];
    for (char& c : noisyRow) c = '-';
    if (columns > 12) noisyRow.replace(size_t(columns) - 12, 12, " noisy input");
    for (size_t i = 0; i < points.size(); ++i) {
        const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
        char& cell = grid[size_t(rowOf(metric.of(points[i]->quality)))][size_t(columnOf(points[i]->gpuMs))];
        cell = (cell == ' ' || cell == '-') ? letterOf(i, onFront) : '+';
    }
    const double top = metric.higherIsBetter ? yHi : yLo, bottom = metric.higherIsBetter ? yLo : yHi;
    char label[64];
    std::string out = "\n" + s.description + ": " + metric.title + " (better is up) against GPU ms\n";
    for (int y = 0; y < rows; ++y) {
        if (y == 0 || y == rows - 1) std::snprintf(label, sizeof label, "%10.4g |", y == 0 ? top : bottom);
        else std::snprintf(label, sizeof label, "%10s |", "");
        out += label + grid[size_t(y)] + "\n";
    }
    std::snprintf(label, sizeof label, "%10s +", "");
    out += label + std::string(size_t(columns), '-') + "\n";
    std::string axis(size_t(12 + columns), ' ');
    axis[12] = '0';
    std::snprintf(label, sizeof label, "%.4g ms", xHi);
    axis.replace(axis.size() - std::string(label).size(), std::string(label).size(), label);
    out += axis + "\n";
    for (size_t i = 0; i < points.size(); ++i) {
        const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
        out += std::string("  ") + letterOf(i, onFront) + " " + points[i]->config + (onFront ? " (front)" : "") + "\n";
    }
    if (points.size() > 26) out += "  * a configuration past the 26th (the table names it)\n";
    return out + "  + several in one place\n";
}

} // namespace hush::cli
