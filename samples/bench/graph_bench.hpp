#pragma once
// hush-bench-graph's options and result rows, shared by the measurements
// (graph_bench.cpp) and their tables and JSON (graph_bench_report.cpp).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <hush/graph/render_graph.hpp>
#include <hush/rhi/rhi.hpp>

#include "bench_report.hpp"

namespace hush::bench::graph_bench {

using hush::graph::MemoryReport;
using hush::rhi::AdapterInfo;
using hush::rhi::AdapterRequest;
using hush::rhi::Extent2D;

struct Options {
    uint32_t compiles = 11;
    uint32_t frames = 60;
    uint32_t warmup = 5;
    std::string output = "bench-results/graph.json";
    std::string commandLine;   // as given, for the results file
    AdapterRequest adapter;
};

// The planning steps of compile_steps.hpp, timed one by one.
constexpr const char* kSteps[] = {"validate", "cull", "order", "lifetimes", "aliasing", "barriers"};
constexpr size_t kStepCount = std::size(kSteps);

struct CompileRow {
    uint32_t passes = 0;
    Stats declareMs, planMs, compileMs;
    std::array<Stats, kStepCount> stepMs;
    size_t barriers = 0;
    MemoryReport memory;
};

struct OverheadResult {
    uint32_t passes = 0;
    uint32_t frames = 0;
    Extent2D size;
    size_t barriersPerFrame = 0;
    Stats graphExecuteMs, graphRecordMs, handExecuteMs, handRecordMs, gpuMs;
    double executeRatio = 0.0, recordRatio = 0.0;
    bool verified = false;
};

struct MemoryRow {
    std::string chain;
    MemoryReport aliased, separate;
    uint64_t deviceBytesAliased = 0, deviceBytesSeparate = 0;   // device memory compile() allocated
};

void printTables(const std::vector<CompileRow>& compiles, const std::vector<OverheadResult>& overheads,
                 const MemoryRow& memory);
std::string toJson(const Options& options, const AdapterInfo& adapter, bool validation,
                   const std::vector<CompileRow>& compiles, const std::vector<OverheadResult>& overheads,
                   const MemoryRow& memory);

} // namespace hush::bench::graph_bench
