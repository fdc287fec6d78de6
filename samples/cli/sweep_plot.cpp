// The sweep's plot, drawn with cairo (SVG and PNG surfaces share the drawing): GPU ms
// per frame on x, the sweep's quality metric on y (better is up), one dot per
// configuration coloured by chain, the Pareto front joined and ringed, each point
// labelled with its configuration's name where labels do not collide (plot_labels.hpp),
// the chains' colours in a legend, the noisy input as a dashed line.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>

#include <cairo-svg.h>
#include <cairo.h>
#include <fontconfig/fontconfig.h>

#include <hush/core/error.hpp>

#include "plot_labels.hpp"
#include "sweep_result.hpp"

namespace hush::cli {
namespace {

constexpr double kWidth = 800, kHeight = 520;
constexpr double kLeft = 80, kRight = 30, kTop = 50, kBottom = 60;

struct Axis {
    double lo, hi, pixelLo, pixelHi;
    double map(double v) const { return pixelLo + (v - lo) / (hi - lo) * (pixelHi - pixelLo); }
};

Axis padded(double lo, double hi, double pixelLo, double pixelHi) {
    if (!(hi > lo)) lo -= 0.5, hi += 0.5;
    const double pad = 0.08 * (hi - lo);
    return {lo - pad, hi + pad, pixelLo, pixelHi};
}

void text(cairo_t* cr, double x, double y, const std::string& s, double size, double alignX = 0.0) {
    cairo_set_font_size(cr, size);
    cairo_text_extents_t e;
    cairo_text_extents(cr, s.c_str(), &e);
    cairo_move_to(cr, x - alignX * e.x_advance, y);
    cairo_show_text(cr, s.c_str());
}

void chainColour(cairo_t* cr, size_t index) {
    static const double palette[][3] = {{0.12, 0.47, 0.71}, {1.0, 0.5, 0.05}, {0.17, 0.63, 0.17},
                                        {0.84, 0.15, 0.16}, {0.58, 0.4, 0.74}, {0.55, 0.34, 0.29}};
    const auto& c = palette[index % 6];
    cairo_set_source_rgb(cr, c[0], c[1], c[2]);
}

void drawAxes(cairo_t* cr, const Axis& x, const Axis& y, const SweepMetric& metric, const std::string& title) {
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, kLeft, kTop, kWidth - kLeft - kRight, kHeight - kTop - kBottom);
    cairo_stroke(cr);
    for (int i = 0; i <= 5; ++i) {
        const double vx = x.lo + (x.hi - x.lo) * i / 5.0, vy = y.lo + (y.hi - y.lo) * i / 5.0;
        char label[32];
        std::snprintf(label, sizeof label, "%.3g", vx);
        text(cr, x.map(vx), kHeight - kBottom + 18, label, 11, 0.5);
        std::snprintf(label, sizeof label, "%.4g", vy);
        text(cr, kLeft - 6, y.map(vy) + 4, label, 11, 1.0);
    }
    text(cr, (kLeft + kWidth - kRight) / 2, kHeight - 15, "GPU ms per frame (median)", 13, 0.5);
    cairo_save(cr);
    cairo_translate(cr, 20, (kTop + kHeight - kBottom) / 2);
    cairo_rotate(cr, -M_PI / 2);
    text(cr, 0, 0, std::string(metric.title) + (metric.higherIsBetter ? " (higher is better)" : " (lower is better)"),
         13, 0.5);
    cairo_restore(cr);
    text(cr, kLeft, 30, title, 15);
}

void drawLabels(cairo_t* cr, const std::vector<const SweepPoint*>& points, const std::vector<size_t>& front,
                const Axis& x, const Axis& y, const SweepMetric& metric, const std::vector<PlotBox>& dots);
void drawLegend(cairo_t* cr, const std::map<std::string, size_t>& chainIndex);

void draw(cairo_t* cr, const SweepResult& result, const SweepSource& source) {
    const auto& metric = sweepMetric(result.metric);
    const auto points = result.pointsOf(source.key);
    const double noisy = metric.of(source.noisy);
    const SweepExtent extent = sweepExtent(points, metric, noisy);
    const Axis x{0.0, extent.msHi > 0.0 ? 1.1 * extent.msHi : 1.0, kLeft, kWidth - kRight};   // time from 0
    // Better is up: lower-is-better metrics run downwards.
    Axis y = padded(extent.lo, extent.hi, kHeight - kBottom, kTop);
    if (!metric.higherIsBetter) std::swap(y.pixelLo, y.pixelHi);
    drawAxes(cr, x, y, metric, "hush sweep: " + source.description);

    const double dashes[] = {6.0, 4.0};
    cairo_set_dash(cr, dashes, 2, 0);
    cairo_set_source_rgb(cr, 0.5, 0.5, 0.5);
    cairo_move_to(cr, kLeft, y.map(noisy));
    cairo_line_to(cr, kWidth - kRight, y.map(noisy));
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    text(cr, kWidth - kRight - 4, y.map(noisy) - 4, "noisy input", 11, 1.0);

    const auto front = paretoFront(points, metric);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, 1.5);
    for (size_t k = 0; k < front.size(); ++k) {
        const auto* p = points[front[k]];
        (k ? cairo_line_to : cairo_move_to)(cr, x.map(p->gpuMs), y.map(metric.of(p->quality)));
    }
    cairo_stroke(cr);
    std::map<std::string, size_t> chainIndex;
    for (const auto& c : result.configs) chainIndex.emplace(c.chain, chainIndex.size());
    std::vector<PlotBox> dots;
    for (size_t i = 0; i < points.size(); ++i) {
        const auto* p = points[i];
        const double px = x.map(p->gpuMs), py = y.map(metric.of(p->quality));
        const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
        const double r = onFront ? 8.5 : 4.0;
        dots.push_back({px - r, py - r, px + r, py + r});
        chainColour(cr, chainIndex[result.config(p->config).chain]);
        cairo_arc(cr, px, py, onFront ? 6.0 : 4.0, 0, 2 * M_PI);
        cairo_fill(cr);
        if (onFront) {
            cairo_set_source_rgb(cr, 0, 0, 0);
            cairo_arc(cr, px, py, 8.5, 0, 2 * M_PI);
            cairo_stroke(cr);
        }
    }
    drawLabels(cr, points, front, x, y, metric, dots);
    drawLegend(cr, chainIndex);
}

// Every front label, and every other one that has a free place (plot_labels.hpp); a
// footnote counts the others, which the report's table lists.
void drawLabels(cairo_t* cr, const std::vector<const SweepPoint*>& points, const std::vector<size_t>& front,
                const Axis& x, const Axis& y, const SweepMetric& metric, const std::vector<PlotBox>& dots) {
    cairo_set_font_size(cr, 10);
    cairo_font_extents_t font;
    cairo_font_extents(cr, &font);
    std::vector<PlotLabel> labels;
    for (size_t i = 0; i < points.size(); ++i) {
        cairo_text_extents_t e;
        cairo_text_extents(cr, points[i]->config.c_str(), &e);
        labels.push_back({x.map(points[i]->gpuMs), y.map(metric.of(points[i]->quality)), e.x_advance,
                          font.ascent + font.descent, std::find(front.begin(), front.end(), i) != front.end()});
    }
    const PlotBox area{kLeft + 2, kTop + 2, kWidth - kRight - 2, kHeight - kBottom - 2};
    const auto boxes = placeLabels(labels, dots, area);
    size_t omitted = 0;
    cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
    for (size_t i = 0; i < points.size(); ++i) {
        if (!boxes[i]) {
            ++omitted;
            continue;
        }
        cairo_move_to(cr, boxes[i]->x0, boxes[i]->y0 + font.ascent);
        cairo_show_text(cr, points[i]->config.c_str());
    }
    if (omitted)
        text(cr, kWidth - kRight, kHeight - 3,
             std::to_string(omitted) + " label" + (omitted > 1 ? "s" : "") + " left out to keep them apart; the report's table lists all",
             9, 1.0);
}

// The chains' colours, in the title line's right end.
void drawLegend(cairo_t* cr, const std::map<std::string, size_t>& chainIndex) {
    std::vector<std::pair<size_t, std::string>> chains;
    for (const auto& [name, index] : chainIndex) chains.emplace_back(index, name);
    std::sort(chains.begin(), chains.end());
    double right = kWidth - kRight;
    cairo_set_font_size(cr, 11);
    for (auto it = chains.rbegin(); it != chains.rend(); ++it) {
        cairo_text_extents_t e;
        cairo_text_extents(cr, it->second.c_str(), &e);
        right -= e.x_advance;
        cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
        cairo_move_to(cr, right, 30);
        cairo_show_text(cr, it->second.c_str());
        chainColour(cr, it->first);
        cairo_arc(cr, right - 8, 26, 4.0, 0, 2 * M_PI);
        cairo_fill(cr);
        right -= 24;
    }
}

void check(cairo_surface_t* surface, const std::string& path) {
    if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS)
        throw Error(ErrorKind::Io, path + ": cannot draw the plot (" +
                                       cairo_status_to_string(cairo_surface_status(surface)) + ")");
}

// cairo's text loads fontconfig's configuration once per process and keeps it, with
// some memory fontconfig itself no longer points to, until exit. Releasing both at exit
// (cairo_debug_reset_static_data exists for memory checkers) lets LeakSanitizer hold
// the CLI to no leaks at all, without a suppression for a font library.
void releaseFontCachesAtExit() {
    static const bool registered = [] {
        std::atexit([] {
            cairo_debug_reset_static_data();
            FcFini();
        });
        return true;
    }();
    (void)registered;
}

} // namespace

void writeSweepPlot(const SweepResult& result, const SweepSource& source, const std::string& svgPath,
                    const std::string& pngPath) {
    releaseFontCachesAtExit();
    cairo_surface_t* svg = cairo_svg_surface_create(svgPath.c_str(), kWidth, kHeight);
    check(svg, svgPath);
    cairo_t* cr = cairo_create(svg);
    draw(cr, result, source);
    cairo_destroy(cr);
    cairo_surface_finish(svg);
    check(svg, svgPath);
    cairo_surface_destroy(svg);

    cairo_surface_t* png = cairo_image_surface_create(CAIRO_FORMAT_RGB24, int(kWidth), int(kHeight));
    cr = cairo_create(png);
    draw(cr, result, source);
    cairo_destroy(cr);
    const cairo_status_t status = cairo_surface_write_to_png(png, pngPath.c_str());
    cairo_surface_destroy(png);
    if (status != CAIRO_STATUS_SUCCESS)
        throw Error(ErrorKind::Io, pngPath + ": cannot write the plot (" + cairo_status_to_string(status) + ")");
}

} // namespace hush::cli
