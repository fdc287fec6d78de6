#include "plot_labels.hpp"

#include <algorithm>
#include <limits>

namespace hush::cli {
namespace {

constexpr double kGap = 9.0;   // from the point's centre to the label, clear of its ring

// The positions a label tries, best first: right of the point (the plot reads left
// to right, time increasing), then left, above, below.
std::vector<PlotBox> candidates(const PlotLabel& l) {
    const double x = l.pointX, y = l.pointY, w = l.width, h = l.height;
    auto box = [&](double left, double top) { return PlotBox{left, top, left + w, top + h}; };
    return {box(x + kGap, y - h - 2), box(x + kGap, y + 2),         box(x + kGap, y - h / 2),
            box(x - kGap - w, y - h - 2), box(x - kGap - w, y + 2), box(x - kGap - w, y - h / 2),
            box(x - w / 2, y - kGap - h), box(x - w / 2, y + kGap)};
}

double covered(const PlotBox& b, const std::vector<PlotBox>& placed, const std::vector<PlotBox>& obstacles) {
    double area = 0;
    for (const auto& p : placed) area += b.overlap(p);
    for (const auto& o : obstacles) area += b.overlap(o);
    return area;
}

} // namespace

double PlotBox::overlap(const PlotBox& o) const {
    const double w = std::min(x1, o.x1) - std::max(x0, o.x0), h = std::min(y1, o.y1) - std::max(y0, o.y0);
    return w > 0 && h > 0 ? w * h : 0.0;
}

bool PlotBox::inside(const PlotBox& a) const { return x0 >= a.x0 && y0 >= a.y0 && x1 <= a.x1 && y1 <= a.y1; }

std::vector<std::optional<PlotBox>> placeLabels(const std::vector<PlotLabel>& labels,
                                                const std::vector<PlotBox>& obstacles, const PlotBox& area) {
    std::vector<std::optional<PlotBox>> out(labels.size());
    std::vector<PlotBox> placed;
    for (const bool required : {true, false}) {
        for (size_t i = 0; i < labels.size(); ++i) {
            if (labels[i].required != required) continue;
            std::optional<PlotBox> best;
            double bestCovered = std::numeric_limits<double>::infinity();
            for (const auto& c : candidates(labels[i])) {
                if (!c.inside(area)) continue;
                const double cover = covered(c, placed, obstacles);
                if (cover < bestCovered) best = c, bestCovered = cover;
                if (cover == 0.0) break;
            }
            // A required label off every free position still shows (inside the plot
            // if it fits anywhere, else at its first position).
            if (!best && required) best = candidates(labels[i]).front();
            if (best && (required || bestCovered == 0.0)) {
                out[i] = best;
                placed.push_back(*best);
            }
        }
    }
    return out;
}

} // namespace hush::cli
