#pragma once
// hush-bench-chains' options and result rows, shared by the measurements
// (chain_bench_timing.cpp: speed, bandwidth, memory; chain_bench_quality.cpp: image
// quality on the tracer's scenes) and their tables and JSON (chain_bench_report.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include <hush/graph/render_graph.hpp>
#include <hush/passes/chain_runner.hpp>
#include <hush/rhi/rhi.hpp>
#include <hush/tracer/frame.hpp>

#include "bench_report.hpp"

namespace hush::bench::chain_bench {

using hush::graph::MemoryReport;
using hush::rhi::AdapterInfo;
using hush::rhi::AdapterRequest;
using hush::rhi::Extent2D;

struct Options {
    std::vector<std::string> chains = {"svgf", "eaw"};
    // Timing: one cornell frame per size, uploaded once, then run warmup + frames times.
    bool timing = true;
    std::vector<Extent2D> sizes = {{640, 360}, {1280, 720}};
    uint32_t warmup = 5;
    uint32_t frames = 20;
    uint32_t probeRuns = 20;   // timed runs of the roofline probe (after 3 warm-up runs)
    // Quality: a short sequence per scene, references on some frames.
    bool quality = true;
    Extent2D qualitySize{128, 128};
    uint32_t qualityFrames = 16;
    std::vector<uint32_t> referenceFrames = {7, 15};
    uint32_t referenceSpp = 256;
    std::vector<std::string> scenes;   // empty: every built-in scene
    std::string output = "bench-results/chains.json";
    AdapterRequest adapter;
    std::string commandLine;   // as given, for the JSON
};

// The device's copy bandwidth at one size: the bandwidth probe's RGBA32F texture
// copy (bandwidth_probe.hpp), (bytes read + bytes written) / median time.
struct Roofline {
    Extent2D size;
    Stats ms;
    double gbps = 0.0;
    std::string timer;
    bool verified = false;
    double otherCpuShare = -1.0;   // as TimingResult's
};

// The device's multiply-add throughput (fma_probe.hpp), measured once per run when a
// chain does arithmetic the bench counts (the rdae network's convolutions).
struct ComputeRoofline {
    bool measured = false;
    Stats ms;
    double gflops = 0.0;   // 2 flops per multiply-add, / median time
    std::string timer;
    bool verified = false;
};

struct PassRow {
    std::string name;
    Stats gpuMs;
    // Unique bytes: every resource the pass reads counted once, every one it writes
    // once (extent x format size), whatever the kernel's footprint.
    uint64_t bytesRead = 0, bytesWritten = 0;
    // An indirect dispatch over the tiles an earlier pass listed (passes/common/
    // tile_list.hpp): it moves the listed tiles' share of those bytes, which the host
    // does not know, so it has no GB/s or roofline fraction (0) and its bytes are not
    // in the frame's.
    bool listedTiles = false;
    double gbps = 0.0;       // (bytesRead + bytesWritten) / median ms
    double ofRoofline = 0.0; // gbps / the roofline's gbps at the same size
    // Counted arithmetic (a convolution's 9 x inputs x outputs per pixel of its level).
    double multiplyAdds = 0.0;
    double gflops = 0.0;              // 2 x multiplyAdds / median ms
    double ofComputeRoofline = 0.0;   // gflops / the compute roofline's
};

struct TimingResult {
    std::string chain;
    Extent2D size;
    uint32_t frames = 0;
    std::vector<PassRow> passes;   // execution order
    Stats totalGpuMs;              // first pass begin to last pass end
    Stats cpuRecordMs;
    double sumOfPassMedians = 0.0;
    uint64_t bytes = 0;            // over all passes but the listed-tiles ones
    double gbps = 0.0, ofRoofline = 0.0;   // bytes / median total
    double multiplyAdds = 0.0;             // counted, over all passes
    double multiplyAddsPerPixel = 0.0;     // of the frame (the padded frame's work / its pixels)
    double gflops = 0.0, ofComputeRoofline = 0.0;   // over the whole frame's median
    size_t barriersPerFrame = 0;
    MemoryReport aliased, unaliased;   // the graph compiled with aliasing on / off
    // Device memory the ChainRunner allocated (its input textures and the graph).
    uint64_t deviceBytesAliased = 0, deviceBytesUnaliased = 0;
    uint64_t nonFiniteOutput = 0;  // display + radiance values after the last frame
    // Share of the host's CPU time that other processes used during the frames
    // (-1: not known). On lavapipe the "GPU" is the host's cores: other work there
    // inflates every figure.
    double otherCpuShare = -1.0;
};

struct QualityScore {
    std::string method;   // "noisy", then the chains
    double rmse = 0.0, ssim = 0.0, psnr = 0.0;   // means over the scored frames
    double temporal = 0.0;                       // mean over consecutive frame pairs
    uint64_t nonFinitePixels = 0;
};

struct QualityRow {
    std::string scene;
    uint32_t scoredFrames = 0;
    double renderSeconds = 0.0;
    std::vector<QualityScore> scores;
};

// chain_bench_timing.cpp
// Every layer but the reference: what any chain may read.
std::vector<tracer::Channel> denoiserChannels();
// Frame 0 of the cornell box's camera path at 1 spp, with denoiserChannels().
tracer::Frame renderTimingFrame(Extent2D size);
Roofline measureRoofline(const rhi::Device& device, Extent2D size, uint32_t runs);
ComputeRoofline measureComputeRoofline(const rhi::Device& device, uint32_t runs);
// Whether the chain has arithmetic the bench counts (then the compute roofline is measured).
bool countsArithmetic(const std::string& chain);
TimingResult measureChainTiming(const rhi::Device& device, const std::string& chain, const tracer::Frame& frame,
                                const Roofline& roofline, const ComputeRoofline& compute, const Options& options);

// chain_bench_quality.cpp: every scene of the options (progress on stdout).
std::vector<QualityRow> measureQuality(const rhi::Device& device, const Options& options);

// chain_bench_report.cpp
void printRooflines(const std::vector<Roofline>& rooflines);
void printComputeRoofline(const ComputeRoofline& compute);
void printTiming(const TimingResult& result, const Roofline& roofline);
// Per-pass arithmetic (multiply-adds, GFLOP/s, share of the compute roofline), for
// chains with counted arithmetic.
void printArithmetic(const TimingResult& result, const ComputeRoofline& compute);
// The paper's per-stage times beside ours, for a chain whose paper gives them (Mara: Table 1).
void printPaperShares(const TimingResult& result);
void printMemory(const std::vector<TimingResult>& results);
void printQuality(const std::vector<QualityRow>& rows, const Options& options);
std::string toJson(const Options& options, const AdapterInfo& adapter, bool validation,
                   const std::vector<Roofline>& rooflines, const ComputeRoofline& compute,
                   const std::vector<TimingResult>& timings, const std::vector<QualityRow>& quality);

} // namespace hush::bench::chain_bench
