#pragma once
// Where a plot's point labels go so that none covers another label or a point:
// each label tries positions around its point in a fixed order and takes the first
// free one inside the plot. Labels that must show (the Pareto front's) are placed
// first and always shown, at their least-covered position when none is free; the
// others are left out when no position is free (the report's table lists every
// configuration), rather than drawn over each other.
#include <optional>
#include <vector>

namespace hush::cli {

struct PlotBox {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;   // x0 <= x1, y0 <= y1 (y down, as cairo)
    double overlap(const PlotBox& other) const;   // the shared area
    bool inside(const PlotBox& area) const;
};

struct PlotLabel {
    double pointX = 0, pointY = 0;   // the point it names
    double width = 0, height = 0;    // the text's extent
    bool required = false;           // always shown
};

// One box per label, in the labels' order: where its text goes, or nullopt when it
// is left out. `obstacles` (the points' dots) are never covered by a free position.
std::vector<std::optional<PlotBox>> placeLabels(const std::vector<PlotLabel>& labels,
                                                const std::vector<PlotBox>& obstacles, const PlotBox& area);

} // namespace hush::cli
