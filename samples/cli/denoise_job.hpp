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
    // Non-empty: each frame's reference is the 'color' layer of the file of the same
    // name in this folder (a high-sample render of the same frames).
    std::string referenceFolder;
    std::string outFolder;
    bool overwrite = false;              // write into a folder with files of unknown origin
    bool writeExr = true;
    bool writePng = true;
    bool sideBySide = false;             // noisy | chains... | reference, on scored frames
    bool dumpGraph = false;              // <out>/graph.<chain>.dot and .json
    // For sweeps, which run many configurations over one sequence:
    std::string outputPrefix;            // outputs go to <out>/<prefix>/<chain>/ (empty: <out>/<chain>/)
    bool pngScoredOnly = false;          // PNGs only of frames with a reference
    bool writeReferencePng = false;      // <prefix>/reference/frame_<i>.png on scored frames
    bool quiet = false;                  // no progress line (the caller shows its own)
    // Radiance layers (and the reference) are multiplied by this after reading; the
    // noisy input and the reference are tonemapped with exposure 1 / this, as the
    // chains must be (their tonemap.exposure): an exposure sweep (hush sweep --exposure).
    float exposure = 1.0f;
    // A lighting change: from the frame of index stepFrame on, radiance and reference
    // are multiplied by stepExposure as well (the tonemap is not compensated: the
    // image brightens, as when every light brightens). hush sweep --lag.
    uint32_t stepFrame = ~0u;
    float stepExposure = 1.0f;
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
    // temporal_artifacts.hpp: per scored frame, the RMSE in recently disoccluded
    // pixels over the RMSE elsewhere; per pair of consecutive scored frames, the
    // temporal error over the references' own.
    std::vector<double> ghosting;
    std::vector<double> flicker;
    uint64_t sanitizedPixels = 0;
    uint64_t nonFiniteOutputs = 0;                 // values in radiance and display (an error)
    std::vector<uint32_t> nonFiniteFrames;
    uint64_t transientBytes = 0, transientUnaliasedBytes = 0, historyBytes = 0;
};

struct DenoiseJobResult {
    uint32_t width = 0, height = 0, frames = 0;
    std::vector<ChainResult> chains;   // "noisy" first
    std::vector<std::string> warnings; // frames left unscored, histories reset at gaps
    double seconds = 0.0;
};

class OutputFolder;

// Checks every frame (size, layers the chains read, index order) before any work;
// one hush::Error lists every problem found.
void checkSequence(const DenoiseJobOptions& options);

DenoiseJobResult runDenoiseJob(const rhi::Device& device, const DenoiseJobOptions& options, OutputFolder& out);

// The table printed to stdout, and the JSON report.
std::string formatReportTables(const DenoiseJobResult& result);
std::string reportJson(const DenoiseJobResult& result, const std::string& adapterName);

double median(std::vector<double> values);
// frame_<i>.exr -> i (tracer::listFrames lists only such names).
uint32_t frameIndexOf(const std::string& path);

// Checks the frames, runs the job on the requested adapter, prints the tables, writes
// report.json and the folder's manifest. Exit code 1 (kExitFailed) when an output
// holds a non-finite value. `out` is the job's folder (made by the caller when it
// writes there too, as hush demo does; else made here from options.outFolder).
int runDenoiseJobAndReport(const DenoiseJobOptions& options, const rhi::AdapterRequest& request,
                           OutputFolder* out = nullptr);

} // namespace hush::cli
