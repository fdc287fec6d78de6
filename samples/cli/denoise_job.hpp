#pragma once
// The denoise job behind `hush denoise` and `hush demo`: every chain over one
// sequence of frame files, side by side. Per frame it writes each chain's output
// (EXR radiance, PNG display), scores the frames that carry a reference (RMSE,
// relative MSE, PSNR, SSIM on tonemapped images, GPU metric nodes), measures the
// temporal error between consecutive outputs, and collects per-pass GPU times. The
// noisy input is scored the same way, as the baseline.
#include <map>
#include <string>
#include <vector>

#include <hush/passes/chain.hpp>
#include <hush/passes/metrics/metrics_evaluator.hpp>
#include <hush/rhi/instance.hpp>
#include <hush/rhi/device.hpp>

namespace hush::cli {

struct DenoiseJobOptions {
    std::vector<std::string> chains;     // built-in names or chain files
    std::vector<std::string> framePaths; // in order
    std::string outFolder;
    bool writeExr = true;
    bool writePng = true;
    bool sideBySide = false;             // noisy | chains... | reference, on scored frames
    std::string dumpGraph;               // path prefix for <chain>.dot/.json; "" = none
};

struct ScoredFrame {
    uint32_t frame = 0;
    passes::ImageMetrics metrics;
};

struct ChainResult {
    std::string name;                              // "svgf", "eaw", "noisy"
    std::vector<std::string> passOrder;
    std::map<std::string, std::vector<double>> passMs;
    std::vector<double> frameMs;
    std::vector<ScoredFrame> scored;
    std::vector<double> temporalError;             // frame i vs i-1, i >= 1
    uint64_t sanitizedPixels = 0;
    uint64_t transientBytes = 0, transientUnaliasedBytes = 0, historyBytes = 0;
};

struct DenoiseJobResult {
    uint32_t width = 0, height = 0, frames = 0;
    std::vector<ChainResult> chains;   // "noisy" first
    double seconds = 0.0;
};

DenoiseJobResult runDenoiseJob(const rhi::Device& device, const DenoiseJobOptions& options);

// The table printed to stdout, and the JSON report.
std::string formatReportTables(const DenoiseJobResult& result);
std::string reportJson(const DenoiseJobResult& result, const std::string& adapterName);

double median(std::vector<double> values);

// Runs the job on the requested adapter, prints the tables, writes report.json.
int runDenoiseJobAndReport(const DenoiseJobOptions& options, const rhi::AdapterRequest& request);

} // namespace hush::cli
