// hush-bench-graph's tables (stdout) and JSON (bench-results/graph.json).
#include <cstdio>
#include <string>
#include <thread>

#include "graph_bench.hpp"
#include "graph_memory_json.hpp"

namespace hush::bench::graph_bench {

void printTables(const std::vector<CompileRow>& compiles, const std::vector<OverheadResult>& overheads,
                 const MemoryRow& m) {
    std::printf("\ncompile (synthetic chains, 16x16 rgba16float, median [min, max] ms)\n");
    std::printf("%7s %24s %24s %24s %9s\n", "passes", "declare", "plan (steps 1-5)", "compile()", "barriers");
    for (const auto& r : compiles) {
        auto cell = [](const Stats& s) {
            char text[64];
            std::snprintf(text, sizeof text, "%.3f [%.3f, %.3f]", s.median, s.min, s.max);
            return std::string(text);
        };
        std::printf("%7u %24s %24s %24s %9zu\n", r.passes, cell(r.declareMs).c_str(), cell(r.planMs).c_str(),
                    cell(r.compileMs).c_str(), r.barriers);
        std::printf("%7s plan steps, median ms:", "");
        for (size_t k = 0; k < kStepCount; ++k) std::printf(" %s %.3f", kSteps[k], r.stepMs[k].median);
        std::printf("\n");
    }

    for (const auto& o : overheads) {
        std::printf("\nper-frame CPU overhead (%u passes, %ux%u rgba16float, %zu barriers per frame; median [min, max] "
                    "ms)\n",
                    o.passes, o.size.width, o.size.height, o.barriersPerFrame);
        std::printf("%-34s %24s %24s %8s\n", "", "render graph", "by hand (rhi)", "ratio");
        auto line = [](const char* what, const Stats& a, const Stats& b, double ratio) {
            std::printf("%-34s %8.4f [%.4f, %.4f] %8.4f [%.4f, %.4f] %8.3f\n", what, a.median, a.min, a.max, b.median,
                        b.min, b.max, ratio);
        };
        line("wait + record + submit", o.graphExecuteMs, o.handExecuteMs, o.executeRatio);
        line("record only (cpuRecordMs)", o.graphRecordMs, o.handRecordMs, o.recordRatio);
        std::printf("GPU time per frame (graph timestamps): median %.3f ms; images %s\n", o.gpuMs.median,
                    o.verified ? "verified" : "DIFFER");
    }
    std::printf("\ntransient memory: %s\n", m.chain.c_str());
    std::printf("%-12s %14s %14s %14s\n", "", "transients MiB", "output MiB", "allocated MiB");
    std::printf("%-12s %14.2f %14.2f %14.2f\n", "aliased", mib(m.aliased.transientAliasedBytes),
                mib(m.aliased.outputBytes), mib(m.deviceBytesAliased));
    std::printf("%-12s %14.2f %14.2f %14.2f\n", "not aliased", mib(m.separate.transientAliasedBytes),
                mib(m.separate.outputBytes), mib(m.deviceBytesSeparate));
}

std::string stepsJson(const CompileRow& r) {
    std::string json = "{";
    for (size_t k = 0; k < kStepCount; ++k)
        json += std::string(k ? ", " : "") + jsonString(kSteps[k]) + ": " + statsJson(r.stepMs[k]);
    return json + "}";
}

std::string toJson(const Options& options, const AdapterInfo& adapter, bool validation,
                   const std::vector<CompileRow>& compiles, const std::vector<OverheadResult>& overheads,
                   const MemoryRow& m) {
    std::string json = resultsHead({.program = "graph", .commandLine = options.commandLine,
                                    .device = adapter.reportFields(), .validation = validation});
    json += "  \"compiles\": " + std::to_string(options.compiles) + ",\n";
    json += "  \"frames\": " + std::to_string(options.frames) + ",\n";
    json += "  \"warmup\": " + std::to_string(options.warmup) + ",\n";
    json += "  \"compile\": [";
    for (size_t i = 0; i < compiles.size(); ++i) {
        const auto& r = compiles[i];
        json += i ? ",\n" : "\n";
        json += "    {\"passes\": " + std::to_string(r.passes) + ", \"texture\": \"16x16 rgba16float\"" +
                ", \"declare_ms\": " + statsJson(r.declareMs) + ", \"plan_ms\": " + statsJson(r.planMs) +
                ", \"plan_steps_ms\": " + stepsJson(r) + ", \"compile_ms\": " + statsJson(r.compileMs) +
                ", \"barriers_per_frame\": " + std::to_string(r.barriers) + ", \"memory\": " + memoryJson(r.memory) +
                "}";
    }
    json += "\n  ],\n";
    json += "  \"overhead\": [";
    for (size_t i = 0; i < overheads.size(); ++i) {
        const auto& o = overheads[i];
        json += i ? ",\n" : "\n";
        json += "    {\"passes\": " + std::to_string(o.passes) + ", \"frames\": " + std::to_string(o.frames) +
                ", \"width\": " + std::to_string(o.size.width) + ", \"height\": " + std::to_string(o.size.height) +
                ", \"format\": \"rgba16float\"" + ", \"barriers_per_frame\": " + std::to_string(o.barriersPerFrame) +
                ",\n     \"graph_execute_ms\": " + statsJson(o.graphExecuteMs) +
                ",\n     \"hand_execute_ms\": " + statsJson(o.handExecuteMs) +
                ",\n     \"graph_record_ms\": " + statsJson(o.graphRecordMs) +
                ",\n     \"hand_record_ms\": " + statsJson(o.handRecordMs) +
                ",\n     \"execute_ratio\": " + jsonNumber(o.executeRatio) +
                ", \"record_ratio\": " + jsonNumber(o.recordRatio) + ", \"gpu_frame_ms\": " + statsJson(o.gpuMs) +
                ", \"verified\": " + (o.verified ? "true" : "false") + "}";
    }
    json += "\n  ],\n";
    json += "  \"memory\": [{\"chain\": " + jsonString(m.chain) + ", \"aliased\": " + memoryJson(m.aliased) +
            ", \"not_aliased\": " + memoryJson(m.separate) +
            ", \"device_bytes_aliased\": " + std::to_string(m.deviceBytesAliased) +
            ", \"device_bytes_not_aliased\": " + std::to_string(m.deviceBytesSeparate) + "}]\n";
    json += "}\n";
    return json;
}

} // namespace hush::bench::graph_bench
