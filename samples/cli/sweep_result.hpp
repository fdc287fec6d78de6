#pragma once
// What a sweep measured: per frame source (a scene at a size, or a frames folder)
// and configuration, GPU time, device memory and quality; the Pareto fronts; and
// sweep.json, which is also the sweep's resume state (written after every
// configuration, "complete": false until the end).
#include <cstdint>
#include <string>
#include <vector>

#include <hush/core/json.hpp>

#include "sweep_config.hpp"

namespace hush::cli {

struct SweepQuality {
    double rmse = 0.0, relMse = 0.0, psnr = 0.0, ssim = 0.0;   // means over the scored frames
    double temporal = 0.0;                                    // mean over consecutive pairs
    // temporal_artifacts.hpp, means; -1 where not measured (flicker needs references
    // on consecutive frames: --reference-pairs).
    double ghosting = -1.0, flicker = -1.0;
    // With --lag: frames after a lighting step (every light doubled) until the RMSE is
    // within 10 % of the same configuration's with the light doubled throughout (0: at
    // once); lagFrames frames
    // were observed, and lag > lagFrames means not within them. -1: not measured.
    double lag = -1.0;
    uint32_t lagFrames = 0;
    uint32_t scoredFrames = 0;
};

struct SweepSource {
    std::string key;          // "cornell-128x128": names its folders and its plot
    std::string description;  // "scene cornell, 128x128, 16 frames"
    uint32_t width = 0, height = 0, frames = 0;
    SweepQuality noisy;       // the input, scored as the chains are
    uint32_t shownFrame = 0;  // the scored frame the report shows (the last)
    // An exposure sweep's sources: the same frames with radiance times `exposure`;
    // `family` is the key they share (the key at exposure 1).
    double exposure = 1.0;
    std::string family;
};

struct SweepPoint {
    std::string source, config;   // keys into the sources and configs
    double gpuMs = 0.0;           // median over the frames of the summed pass times
    double otherCpuShare = -1.0;  // other processes' share of the CPU meanwhile (-1: unknown)
    uint64_t deviceBytes = 0;     // the graph's transient (aliased) + history bytes
    SweepQuality quality;
    uint64_t nonFiniteOutputs = 0;
};

// The metrics a front can be taken on; higherIsBetter for PSNR and SSIM.
struct SweepMetric {
    const char* key;
    const char* title;
    bool higherIsBetter;
    double (*of)(const SweepQuality&);
};
const std::vector<SweepMetric>& sweepMetrics();
// hush::Error listing the keys when `key` is none of them.
const SweepMetric& sweepMetric(const std::string& key);

// The indices of `points` (over one source) that no other point beats on both GPU
// time and `metric`: lower or equal time and better or equal quality, one of them
// strictly. Sorted by time.
std::vector<size_t> paretoFront(const std::vector<const SweepPoint*>& points, const SweepMetric& metric);

// What a plot of one source spans: GPU ms from 0 to the slowest configuration's, and
// `metric` over the configurations and the noisy input's value. Both plots use it.
struct SweepExtent {
    double msHi = 0.0;
    double lo = 0.0, hi = 0.0;
};
SweepExtent sweepExtent(const std::vector<const SweepPoint*>& points, const SweepMetric& metric, double noisy);

struct SweepResult {
    std::string metric = "ssim";      // the plots' and the table's quality axis
    std::vector<SweepSource> sources;
    std::vector<SweepConfig> configs;
    std::vector<SweepPoint> points;   // sources x configs, as measured so far
    bool complete = false;
    core::Json environment;           // core::toJson(RunEnvironment)

    const SweepPoint* find(const std::string& source, const std::string& config) const;
    std::vector<const SweepPoint*> pointsOf(const std::string& source) const;
    const SweepConfig& config(const std::string& name) const;
};

// sweep.json; and reading it back (to resume, or for `hush denoise --budget-ms`).
std::string sweepJson(const SweepResult& result);
SweepResult readSweepJson(const std::string& path);
std::string sweepCsv(const SweepResult& result);
// A ratio with three decimals, "-" when not measured (negative).
std::string ratioText(double value);
// A lag in frames: "3", "> 8" (not back within the frames observed), "-".
std::string lagText(const SweepQuality& q);
// The table printed at the end: every point, the front marked.
std::string sweepTable(const SweepResult& result);
// With several exposures: per source family and configuration, RMSE at each exposure
// over RMSE at exposure 1 (empty when the sweep has one exposure).
std::string sweepExposureTable(const SweepResult& result);

// sweep_plot.cpp: <stem>.svg and <stem>.png, GPU ms against the metric, one point
// per configuration, the front joined and highlighted, points labelled where labels stay apart.
void writeSweepPlot(const SweepResult& result, const SweepSource& source, const std::string& svgPath,
                    const std::string& pngPath);

// sweep_text_plot.cpp: the same plot in text (`columns` x `rows` cells), a letter per
// configuration in the table's order, uppercase on the front, and its key.
std::string sweepTextPlot(const SweepResult& result, const SweepSource& source, int columns = 64, int rows = 16);

// sweep_html.cpp: the report page. `files` gives each image's path relative to it.
struct SweepReportFiles {
    std::string plotPng(const SweepSource& s) const { return "plot-" + s.key + ".png"; }
    std::string plotSvg(const SweepSource& s) const { return "plot-" + s.key + ".svg"; }
    std::string image(const SweepSource& s, const std::string& folder) const;   // runs/<key>/<folder>/frame_<i>.png
};
std::string sweepHtml(const SweepResult& result, const SweepReportFiles& files);

} // namespace hush::cli

namespace hush::cli {

// Budget mode (`hush denoise --budget-ms`): the configuration of best mean quality
// (the sweep's metric, over its sources) among those whose GPU time is within
// `budgetMs` on every source. `why` says which and why, with the runner-up and the
// best one over the budget. hush::Error naming the fastest configuration's time when
// none fits.
struct BudgetChoice {
    std::string config;
    std::string why;
};
BudgetChoice chooseWithinBudget(const SweepResult& result, double budgetMs);

} // namespace hush::cli
