// hush-bench-chains' tables (markdown, on stdout) and JSON (bench-results/chains.json).
#include <cstdio>
#include <string>
#include <thread>

#include "chain_bench.hpp"
#include "paper_stage_times.hpp"
#include "graph_memory_json.hpp"

namespace hush::bench::chain_bench {
namespace {

std::string sizeText(Extent2D size) { return std::to_string(size.width) + "x" + std::to_string(size.height); }

} // namespace

void printRooflines(const std::vector<Roofline>& rooflines) {
    std::printf("\nroofline: RGBA32F storage-texture copy (bandwidth probe), (read + written) / median\n\n");
    std::printf("| size | median ms | min ms | max ms | GB/s | timer | others' CPU share |\n"
                "| --- | ---: | ---: | ---: | ---: | --- | ---: |\n");
    for (const auto& r : rooflines)
        std::printf("| %s | %.3f | %.3f | %.3f | %.2f | %s%s | %.0f %% |\n", sizeText(r.size).c_str(), r.ms.median,
                    r.ms.min, r.ms.max, r.gbps, r.timer.c_str(), r.verified ? "" : " COPY MISMATCH",
                    100.0 * r.otherCpuShare);
}

void printComputeRoofline(const ComputeRoofline& c) {
    if (!c.measured) return;
    std::printf("\ncompute roofline: vec4 multiply-adds, 8 independent chains per invocation (bench/fma.comp): "
                "%.2f GFLOP/s (median %.3f ms, min %.3f, max %.3f; %s)%s\n",
                c.gflops, c.ms.median, c.ms.min, c.ms.max, c.timer.c_str(), c.verified ? "" : " RESULT MISMATCH");
}

void printArithmetic(const TimingResult& t, const ComputeRoofline& compute) {
    if (t.multiplyAdds <= 0.0) return;
    std::printf("\n%s at %s, arithmetic: %.0f multiply-adds per pixel, %.2f G per frame; %.2f GFLOP/s over the "
                "frame, %.0f %% of the compute roofline (%.2f GFLOP/s)\n\n",
                t.chain.c_str(), sizeText(t.size).c_str(), t.multiplyAddsPerPixel, t.multiplyAdds * 1e-9, t.gflops,
                100.0 * t.ofComputeRoofline, compute.gflops);
    std::printf("| layer | median ms | G multiply-adds | GFLOP/s | of compute roofline |\n"
                "| --- | ---: | ---: | ---: | ---: |\n");
    for (const auto& p : t.passes)
        if (p.multiplyAdds > 0.0)
            std::printf("| %s | %.3f | %.3f | %.2f | %.0f %% |\n", p.name.c_str(), p.gpuMs.median, p.multiplyAdds * 1e-9,
                        p.gflops, 100.0 * p.ofComputeRoofline);
}

void printTiming(const TimingResult& t, const Roofline& roofline) {
    std::printf("\n%s at %s: %u frames, GPU %.2f ms per frame (median; min %.2f, max %.2f), CPU record %.3f ms, "
                "%zu barriers per frame; roofline %.2f GB/s; other processes used %.0f %% of the host's CPU time\n\n",
                t.chain.c_str(), sizeText(t.size).c_str(), t.frames, t.totalGpuMs.median, t.totalGpuMs.min,
                t.totalGpuMs.max, t.cpuRecordMs.median, t.barriersPerFrame, roofline.gbps, 100.0 * t.otherCpuShare);
    std::printf("| pass | median ms | min | max | MiB read | MiB written | GB/s | of roofline |\n"
                "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (const auto& p : t.passes)
        if (p.listedTiles)
            std::printf("| %s | %.3f | %.3f | %.3f | listed tiles of %.2f | of %.2f | - | - |\n", p.name.c_str(),
                        p.gpuMs.median, p.gpuMs.min, p.gpuMs.max, mib(p.bytesRead), mib(p.bytesWritten));
        else
            std::printf("| %s | %.3f | %.3f | %.3f | %.2f | %.2f | %.2f | %.0f %% |\n", p.name.c_str(), p.gpuMs.median,
                        p.gpuMs.min, p.gpuMs.max, mib(p.bytesRead), mib(p.bytesWritten), p.gbps, 100.0 * p.ofRoofline);
    std::printf("| **frame** (sum of pass medians %.3f) | %.3f | %.3f | %.3f | %.2f (both) | | %.2f | %.0f %% |\n",
                t.sumOfPassMedians, t.totalGpuMs.median, t.totalGpuMs.min, t.totalGpuMs.max, mib(t.bytes), t.gbps,
                100.0 * t.ofRoofline);
    if (t.nonFiniteOutput != 0) std::printf("WARNING: %llu non-finite output values\n",
                                            static_cast<unsigned long long>(t.nonFiniteOutput));
}

void printPaperShares(const TimingResult& t) {
    const auto& stages = paperStages(t.chain);
    if (stages.empty()) return;
    auto msOf = [&](const PaperStage& stage) {
        double ms = 0.0;
        for (const auto& p : t.passes)
            for (auto name : stage.passes) ms += p.name == name ? p.gpuMs.median : 0.0;
        return ms;
    };
    double ours = 0.0, paper = 0.0;
    for (const auto& stage : stages) ours += msOf(stage), paper += stage.paperMs;
    std::printf("\n%s at %s against the paper's stage times (share of the numbered stages' sum; the paper: "
                "1280x720 on a Titan X)\n\n| stage | ms | share | paper ms | paper share |\n"
                "| --- | ---: | ---: | ---: | ---: |\n",
                t.chain.c_str(), sizeText(t.size).c_str());
    for (const auto& stage : stages) {
        const double ms = msOf(stage);
        std::printf("| %.*s | %.3f | %.1f %% | %.2f | %.1f %% |\n", int(stage.label.size()), stage.label.data(), ms,
                    ours > 0 ? 100.0 * ms / ours : 0.0, stage.paperMs, 100.0 * stage.paperMs / paper);
    }
    std::printf("| sum | %.3f | | %.2f | |\n", ours, paper);
}

void printMemory(const std::vector<TimingResult>& results) {
    std::printf("\nmemory (MiB): transients with aliasing (one shared block) and without, histories (both halves), "
                "outputs; device memory the ChainRunner allocated (inputs + graph)\n\n");
    std::printf("| chain | size | transients aliased | not aliased | aliased / not | history | outputs | "
                "device, aliased | device, not aliased |\n"
                "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (const auto& t : results) {
        const double ratio = t.unaliased.transientAliasedBytes
                                 ? double(t.aliased.transientAliasedBytes) / double(t.unaliased.transientAliasedBytes)
                                 : 0.0;
        std::printf("| %s | %s | %.2f | %.2f | %.0f %% | %.2f | %.2f | %.2f | %.2f |\n", t.chain.c_str(),
                    sizeText(t.size).c_str(), mib(t.aliased.transientAliasedBytes),
                    mib(t.unaliased.transientAliasedBytes), 100.0 * ratio, mib(t.aliased.historyBytes),
                    mib(t.aliased.outputBytes), mib(t.deviceBytesAliased), mib(t.deviceBytesUnaliased));
    }
}

void printQuality(const std::vector<QualityRow>& rows, const Options& o) {
    std::printf("\nquality: %ux%u, %u frames, references at %u spp on %zu frame(s); RMSE, PSNR and SSIM against the "
                "reference (means over the scored frames), temporal error (mean over consecutive pairs); all on "
                "tonemapped display values\n\n",
                o.qualitySize.width, o.qualitySize.height, o.qualityFrames, o.referenceSpp, o.referenceFrames.size());
    std::printf("| scene | method | RMSE | PSNR dB | SSIM | temporal error |\n"
                "| --- | --- | ---: | ---: | ---: | ---: |\n");
    for (const auto& row : rows)
        for (const auto& s : row.scores)
            std::printf("| %s | %s | %.4f | %.2f | %.4f | %.5f |%s\n", row.scene.c_str(), s.method.c_str(), s.rmse,
                        s.psnr, s.ssim, s.temporal, s.nonFinitePixels ? " (non-finite pixels!)" : "");
}

std::string toJson(const Options& o, const AdapterInfo& adapter, bool validation,
                   const std::vector<Roofline>& rooflines, const ComputeRoofline& compute,
                   const std::vector<TimingResult>& timings, const std::vector<QualityRow>& quality) {
    std::string json = resultsHead({.program = "chains", .commandLine = o.commandLine,
                                    .device = adapter.reportFields(), .validation = validation});
    json += "  \"warmup\": " + std::to_string(o.warmup) + ", \"frames\": " + std::to_string(o.frames) +
            ", \"probe_runs\": " + std::to_string(o.probeRuns) + ",\n";

    json += "  \"rooflines\": [";
    for (size_t i = 0; i < rooflines.size(); ++i) {
        const auto& r = rooflines[i];
        json += std::string(i ? ",\n" : "\n") + "    {\"kernel\": \"texture rgba32f\", \"width\": " +
                std::to_string(r.size.width) + ", \"height\": " + std::to_string(r.size.height) +
                ", \"ms\": " + statsJson(r.ms) + ", \"gbps\": " + jsonNumber(r.gbps) + ", \"timer\": " +
                jsonString(r.timer) + ", \"verified\": " + (r.verified ? "true" : "false") +
                ", \"other_processes_cpu_share\": " + jsonNumber(r.otherCpuShare) + "}";
    }
    json += "\n  ],\n";
    if (compute.measured)
        json += "  \"compute_roofline\": {\"kernel\": \"vec4 fma\", \"ms\": " + statsJson(compute.ms) +
                ", \"gflops\": " + jsonNumber(compute.gflops) + ", \"timer\": " + jsonString(compute.timer) +
                ", \"verified\": " + (compute.verified ? "true" : "false") + "},\n";
    json += "  \"timing\": [";
    for (size_t i = 0; i < timings.size(); ++i) {
        const auto& t = timings[i];
        json += std::string(i ? ",\n" : "\n") + "    {\"chain\": " + jsonString(t.chain) +
                ", \"width\": " + std::to_string(t.size.width) + ", \"height\": " + std::to_string(t.size.height) +
                ", \"frames\": " + std::to_string(t.frames) + ",\n     \"gpu_frame_ms\": " + statsJson(t.totalGpuMs) +
                ", \"cpu_record_ms\": " + statsJson(t.cpuRecordMs) +
                ", \"sum_of_pass_medians_ms\": " + jsonNumber(t.sumOfPassMedians) +
                ", \"bytes\": " + std::to_string(t.bytes) + ", \"gbps\": " + jsonNumber(t.gbps) +
                ", \"of_roofline\": " + jsonNumber(t.ofRoofline) +
                ", \"barriers_per_frame\": " + std::to_string(t.barriersPerFrame) +
                ", \"multiply_adds\": " + jsonNumber(t.multiplyAdds) +
                ", \"multiply_adds_per_pixel\": " + jsonNumber(t.multiplyAddsPerPixel) +
                ", \"gflops\": " + jsonNumber(t.gflops) + ", \"of_compute_roofline\": " + jsonNumber(t.ofComputeRoofline) +
                ", \"non_finite_output_values\": " + std::to_string(t.nonFiniteOutput) +
                ", \"other_processes_cpu_share\": " + jsonNumber(t.otherCpuShare) +
                ",\n     \"memory\": {\"aliased\": " + memoryJson(t.aliased) +
                ", \"not_aliased\": " + memoryJson(t.unaliased) +
                ", \"device_bytes_aliased\": " + std::to_string(t.deviceBytesAliased) +
                ", \"device_bytes_not_aliased\": " + std::to_string(t.deviceBytesUnaliased) + "},\n     \"passes\": [";
        for (size_t k = 0; k < t.passes.size(); ++k) {
            const auto& p = t.passes[k];
            json += std::string(k ? ",\n" : "\n") + "       {\"name\": " + jsonString(p.name) +
                    ", \"gpu_ms\": " + statsJson(p.gpuMs) + ", \"bytes_read\": " + std::to_string(p.bytesRead) +
                    ", \"bytes_written\": " + std::to_string(p.bytesWritten) + ", \"gbps\": " + jsonNumber(p.gbps) +
                    ", \"of_roofline\": " + jsonNumber(p.ofRoofline) +
                    ", \"listed_tiles\": " + (p.listedTiles ? "true" : "false") +
                    (p.multiplyAdds > 0.0 ? ", \"multiply_adds\": " + jsonNumber(p.multiplyAdds) + ", \"gflops\": " +
                                                jsonNumber(p.gflops) + ", \"of_compute_roofline\": " +
                                                jsonNumber(p.ofComputeRoofline)
                                          : std::string()) +
                    "}";
        }
        json += "]}";
    }
    json += "\n  ],\n  \"quality\": {\"width\": " + std::to_string(o.qualitySize.width) +
            ", \"height\": " + std::to_string(o.qualitySize.height) +
            ", \"frames\": " + std::to_string(o.qualityFrames) + ", \"reference_spp\": " +
            std::to_string(o.referenceSpp) + ", \"reference_frames\": [";
    for (size_t i = 0; i < o.referenceFrames.size(); ++i)
        json += (i ? ", " : "") + std::to_string(o.referenceFrames[i]);
    json += "],\n   \"scenes\": [";
    for (size_t i = 0; i < quality.size(); ++i) {
        const auto& row = quality[i];
        json += std::string(i ? ",\n" : "\n") + "    {\"scene\": " + jsonString(row.scene) +
                ", \"scored_frames\": " + std::to_string(row.scoredFrames) +
                ", \"render_seconds\": " + jsonNumber(row.renderSeconds) + ", \"methods\": [";
        for (size_t k = 0; k < row.scores.size(); ++k) {
            const auto& s = row.scores[k];
            json += std::string(k ? ", " : "") + "{\"method\": " + jsonString(s.method) +
                    ", \"rmse\": " + jsonNumber(s.rmse) + ", \"psnr\": " + jsonNumber(s.psnr) +
                    ", \"ssim\": " + jsonNumber(s.ssim) + ", \"temporal_error\": " + jsonNumber(s.temporal) +
                    ", \"non_finite_pixels\": " + std::to_string(s.nonFinitePixels) + "}";
        }
        json += "]}";
    }
    json += "\n  ]}\n}\n";
    return json;
}

} // namespace hush::bench::chain_bench
