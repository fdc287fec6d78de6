// hush-bench-bandwidth: the device's copy bandwidth, the roofline every later
// pass is measured against. A copy kernel over RGBA16F and RGBA32F storage
// textures and over storage buffers (vec4 per invocation), at 1280x720 and
// 3840x2160, next to host memcpy of the same byte counts. Prints a table and
// writes bench-results/bandwidth.json.
#include <charconv>
#include <cstdio>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <hush/rhi/rhi.hpp>

#include "bandwidth_probe.hpp"
#include "bench_report.hpp"
#include "fma_probe.hpp"

namespace hush::bench {
namespace {

using namespace hush::rhi;

constexpr std::string_view kUsage =
    "usage: hush-bench-bandwidth [--runs N] [--warmup N] [--output PATH] [--adapter TEXT]\n"
    "\n"
    "Measures copy bandwidth: a compute kernel that reads and writes every texel of an\n"
    "RGBA16F or RGBA32F storage texture, or every vec4 of a storage buffer, at 1280x720\n"
    "and 3840x2160, and host memcpy of the same byte counts. Reports the median, min and\n"
    "max time of N runs (GPU timestamps) after warm-up runs, and effective bandwidth =\n"
    "(bytes read + bytes written) / median time.\n"
    "\n"
    "options:\n"
    "  --runs N        timed runs per case (default 20)\n"
    "  --warmup N      untimed runs before them (default 3)\n"
    "  --output PATH   JSON results (default bench-results/bandwidth.json)\n"
    "  --adapter TEXT  use the first adapter whose name contains TEXT (default: HUSH_ADAPTER)\n";

struct Options {
    uint32_t runs = 20;
    uint32_t warmup = 3;
    std::string output = "bench-results/bandwidth.json";
    std::string commandLine;   // as given, for the results file
    AdapterRequest adapter;
};

struct Row {
    ProbeCase probe;
    ProbeTimings timings;
    Stats ms;
    double gbps = 0.0;
    std::string skipped;   // why the case could not run on this adapter
};

// Returns false when the program should just print the usage and stop.
bool parseOptions(int argc, char** argv, Options& options) {
    for (int i = 1; i < argc; ++i) {
        std::string_view arg = argv[i];
        if (arg == "--help" || arg == "-h") {
            return false;
        }
        auto value = [&]() -> std::string_view {
            if (i + 1 >= argc) {
                throw Error(ErrorKind::InvalidArgument, std::string(arg) + " needs a value");
            }
            return argv[++i];
        };
        if (arg == "--runs") {
            options.runs = core::parseCount(value(), arg, 1);
        } else if (arg == "--warmup") {
            options.warmup = core::parseCount(value(), arg, 0);
        } else if (arg == "--output") {
            options.output = value();
        } else if (arg == "--adapter") {
            options.adapter.nameContains = value();
            options.adapter.nameFromEnvironment = false;
        } else {
            throw Error(ErrorKind::InvalidArgument,
                        "unknown argument '" + std::string(arg) + "' (see hush-bench-bandwidth --help)");
        }
    }
    return true;
}

std::vector<ProbeCase> allCases() {
    std::vector<ProbeCase> cases;
    for (Extent2D size : {Extent2D{1280, 720}, Extent2D{3840, 2160}}) {
        cases.push_back({"texture rgba16f", ProbeKind::Texture, Format::RGBA16Float, size, 8});
        cases.push_back({"texture rgba32f", ProbeKind::Texture, Format::RGBA32Float, size, 16});
        cases.push_back({"buffer vec4", ProbeKind::Buffer, Format::Undefined, size, 16});
        cases.push_back({"host memcpy", ProbeKind::HostMemcpy, Format::Undefined, size, 8});
        cases.push_back({"host memcpy", ProbeKind::HostMemcpy, Format::Undefined, size, 16});
    }
    return cases;
}

std::string sizeText(Extent2D size) {
    return std::to_string(size.width) + "x" + std::to_string(size.height);
}

void printTable(const std::vector<Row>& rows) {
    std::printf("\n%-16s %-10s %5s %10s %10s %10s %10s %9s  %s\n", "kernel", "size", "B/px", "MiB moved",
                "median ms", "min ms", "max ms", "GB/s", "timer");
    for (const Row& row : rows) {
        const ProbeCase& p = row.probe;
        double mib = 2.0 * double(p.bytes()) / (1024.0 * 1024.0);
        std::printf("%-16s %-10s %5u %10.1f ", p.kernel.c_str(), sizeText(p.size).c_str(), p.bytesPerPixel, mib);
        if (!row.skipped.empty()) {
            std::printf("skipped: %s\n", row.skipped.c_str());
            continue;
        }
        std::printf("%10.3f %10.3f %10.3f %9.2f  %s%s\n", row.ms.median, row.ms.min, row.ms.max, row.gbps,
                    row.timings.timer.c_str(), row.timings.verified ? "" : "  COPY MISMATCH");
    }
    std::printf("\nGB/s = (bytes read + bytes written) / median time, 1 GB = 1e9 bytes.\n");
}

std::string toJson(const Options& options, const AdapterInfo& adapter, const std::vector<Row>& rows) {
    std::string json = resultsHead({.program = "bandwidth", .commandLine = options.commandLine,
                                    .device = adapter.reportFields(), .validation = false});
    json += "  \"runs\": " + std::to_string(options.runs) + ",\n";
    json += "  \"warmup\": " + std::to_string(options.warmup) + ",\n";
    json += "  \"results\": [";
    for (size_t i = 0; i < rows.size(); ++i) {
        const Row& row = rows[i];
        const ProbeCase& p = row.probe;
        json += i ? ",\n" : "\n";
        json += "    {\"kernel\": " + jsonString(p.kernel) + ", \"width\": " + std::to_string(p.size.width) +
                ", \"height\": " + std::to_string(p.size.height) +
                ", \"bytes_per_pixel\": " + std::to_string(p.bytesPerPixel) +
                ", \"bytes_read\": " + std::to_string(p.bytes()) + ", \"bytes_written\": " + std::to_string(p.bytes());
        if (row.skipped.empty()) {
            json += ", \"median_ms\": " + jsonNumber(row.ms.median) + ", \"min_ms\": " + jsonNumber(row.ms.min) +
                    ", \"max_ms\": " + jsonNumber(row.ms.max) + ", \"gbps\": " + jsonNumber(row.gbps) +
                    ", \"timer\": " + jsonString(row.timings.timer) +
                    ", \"verified\": " + (row.timings.verified ? "true" : "false") + "}";
        } else {
            json += ", \"skipped\": " + jsonString(row.skipped) + "}";
        }
    }
    json += "\n  ]\n}\n";
    return json;
}

int run(const Options& options) {
    Instance instance = Instance::create();
    Adapter adapter = instance.requestAdapter(options.adapter);
    const AdapterInfo& info = adapter.info();
    std::printf("[bandwidth] adapter: %s (%s, %s)\n", info.name.c_str(), info.driverName.c_str(),
                info.driverInfo.c_str());
    std::printf("[bandwidth] %u warm-up + %u timed runs per case, validation %s\n", options.warmup, options.runs,
                instance.validationEnabled() ? "on (slower: figures not representative)" : "off");
    Device device = adapter.createDevice({.label = "hush-bench-bandwidth"});

    std::vector<Row> rows;
    bool allVerified = true;
    for (const ProbeCase& probe : allCases()) {
        std::printf("[bandwidth] %-16s %-10s %2u B/px ... ", probe.kernel.c_str(), sizeText(probe.size).c_str(),
                    probe.bytesPerPixel);
        std::fflush(stdout);
        Row row{.probe = probe};
        try {
            row.timings = probe.kind == ProbeKind::HostMemcpy
                              ? runHostProbe(probe, options.warmup, options.runs)
                              : runDeviceProbe(device, probe, options.warmup, options.runs);
            row.ms = summarize(row.timings.ms);
            row.gbps = 2.0 * double(probe.bytes()) / (row.ms.median * 1e-3) / 1e9;
            allVerified = allVerified && row.timings.verified;
            std::printf("median %.3f ms%s\n", row.ms.median, row.timings.verified ? "" : " (COPY MISMATCH)");
        } catch (const Error& error) {
            // A limit of this adapter (format, binding size) skips the case, not the run.
            if (error.kind() != ErrorKind::Unsupported) {
                throw;
            }
            row.skipped = error.what();
            std::printf("skipped\n");
        }
        rows.push_back(std::move(row));
        device.waitIdle();
    }

    printTable(rows);
    // The compute roofline beside the copy one: what a convolution's arithmetic meets.
    std::printf("[bandwidth] compute: vec4 multiply-adds ... ");
    std::fflush(stdout);
    const FmaTimings fma = runFmaProbe(device, options.warmup, options.runs);
    const Stats fmaMs = summarize(fma.ms);
    const double gflops = double(fma.flops) / (fmaMs.median * 1e6);
    std::printf("%.2f GFLOP/s (median %.3f ms, min %.3f, max %.3f, %.3g flops per run; %s)%s\n", gflops, fmaMs.median,
                fmaMs.min, fmaMs.max, double(fma.flops), fma.timer.c_str(), fma.verified ? "" : " RESULT MISMATCH");
    allVerified = allVerified && fma.verified;
    std::string json = toJson(options, info, rows);
    json.insert(json.rfind("\n}"), ",\n  \"compute\": {\"kernel\": \"vec4 fma\", \"flops_per_run\": " +
                                       std::to_string(fma.flops) + ", \"median_ms\": " + jsonNumber(fmaMs.median) +
                                       ", \"min_ms\": " + jsonNumber(fmaMs.min) + ", \"max_ms\": " +
                                       jsonNumber(fmaMs.max) + ", \"gflops\": " + jsonNumber(gflops) +
                                       ", \"verified\": " + (fma.verified ? "true" : "false") + "}");
    writeResults(options.output, json);
    std::printf("[bandwidth] wrote %s\n", options.output.c_str());
    if (!allVerified) {
        std::fprintf(stderr, "hush-bench-bandwidth: a copy did not reproduce its source; figures are suspect\n");
        return 1;
    }
    // With HUSH_VALIDATION=1 the barriers above are checked too; a message means a bug here.
    if (size_t messages = instance.validationMessageCount(); messages != 0) {
        std::fprintf(stderr, "hush-bench-bandwidth: %zu validation message(s)\n", messages);
        return 1;
    }
    return 0;
}

} // namespace
} // namespace hush::bench

int main(int argc, char** argv) {
    return hush::bench::guardedMain("hush-bench-bandwidth", [&] {
        hush::bench::Options options;
        options.commandLine = hush::bench::commandLineOf(argc, argv);
        if (!hush::bench::parseOptions(argc, argv, options)) {
            std::printf("%.*s", int(hush::bench::kUsage.size()), hush::bench::kUsage.data());
            return 0;
        }
        return hush::bench::run(options);
    });
}
