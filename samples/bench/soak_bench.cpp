// hush-bench-soak: each chain run for thousands of frames as a long-lived application
// runs it (samples/soak/soak.hpp: looped scenes, a camera cut and a size change every
// segment), sampling the process's resident memory, the device memory hush holds and
// the RHI's live objects at each segment's end. Prints a table per chain and the
// fitted growth per 1,000 frames (zero when nothing leaks); writes
// bench-results/soak.json.
#include <cstdio>
#include <string>
#include <vector>

#include <hush/core/arguments.hpp>
#include <hush/core/error.hpp>
#include <hush/passes/chain_file.hpp>
#include <hush/rhi/rhi.hpp>

#include "bench_report.hpp"
#include "soak.hpp"

using namespace hush;

namespace {

struct Options {
    std::vector<std::string> chains = {"eaw", "svgf", "bmfr", "mara", "rdae"};
    uint32_t frames = 10000;
    uint32_t segment = 1000;
    std::string output = "bench-results/soak.json";
};

constexpr const char* kUsage =
    "usage: hush-bench-soak [--chains LIST (eaw,svgf,bmfr,mara,rdae)] [--frames N (10000)]\n"
    "                       [--segment N (1000)] [--output PATH (bench-results/soak.json)]\n";

Options parse(int argc, char** argv) {
    Options o;
    std::vector<std::string_view> args(argv + 1, argv + argc);
    std::string v;
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--help") {
            std::printf("%s", kUsage);
            std::exit(0);
        } else if (core::takeOption(args, i, "--chains", v)) o.chains = core::splitList(v);
        else if (core::takeOption(args, i, "--frames", v)) o.frames = core::parseCount(v, "--frames", 1);
        else if (core::takeOption(args, i, "--segment", v)) o.segment = core::parseCount(v, "--segment", 1);
        else if (core::takeOption(args, i, "--output", v)) o.output = v;
        else throw Error(ErrorKind::InvalidArgument, "unknown argument '" + std::string(args[i]) + "'\n" + kUsage);
    }
    return o;
}

std::string sampleJson(const soak::SoakSample& s) {
    return "{\"frame\": " + std::to_string(s.frame) + ", \"width\": " + std::to_string(s.size.width) +
           ", \"height\": " + std::to_string(s.size.height) + ", \"scene\": " + bench::jsonString(s.scene) +
           ", \"residentBytes\": " + std::to_string(s.residentBytes) + ", \"deviceBytes\": " +
           std::to_string(s.deviceBytes) + ", \"liveObjects\": " + std::to_string(s.liveObjects) +
           ", \"nonFinite\": " + std::to_string(s.nonFinite) + ", \"msPerFrame\": " + bench::jsonNumber(s.msPerFrame) + "}";
}

} // namespace

int main(int argc, char** argv) {
    return bench::guardedMain("hush-bench-soak", [&] {
        const Options options = parse(argc, argv);
        for (const auto& chain : options.chains) passes::makeChain(chain);   // a bad name fails before any work
        auto instance = rhi::Instance::create();
        auto adapter = instance.requestAdapter({});
        auto device = adapter.createDevice({.label = "hush-bench-soak"});
        std::printf("hush-bench-soak on %s: %u frames per chain, a cut and a size change every %u\n",
                    adapter.info().name.c_str(), options.frames, options.segment);
        std::string rows;
        for (const auto& chain : options.chains) {
            std::printf("\n%-6s %7s %9s %-12s %10s %12s %8s %9s %8s\n", "chain", "frame", "size", "scene", "RSS MiB",
                        "device MiB", "objects", "nonfinite", "ms/frame");
            soak::SoakPlan plan;
            plan.chain = chain;
            plan.frames = options.frames;
            plan.segmentFrames = options.segment;
            std::string samples;
            const auto result = soak::runSoak(device, plan, [&](const soak::SoakSample& s) {
                std::printf("%-6s %7u %4ux%-4u %-12s %10.1f %12.2f %8lld %9llu %8.2f\n", chain.c_str(), s.frame,
                            s.size.width, s.size.height, s.scene.c_str(), double(s.residentBytes) / 1048576.0,
                            double(s.deviceBytes) / 1048576.0, static_cast<long long>(s.liveObjects),
                            static_cast<unsigned long long>(s.nonFinite), s.msPerFrame);
                std::fflush(stdout);
                samples += std::string(samples.empty() ? "" : ",\n") + "      " + sampleJson(s);
            });
            std::printf("%-6s growth per 1,000 frames (same-size segments): RSS %+.1f KiB, device %+.1f KiB, "
                        "objects %+.2f\n",
                        chain.c_str(), result.residentBytesPer1000 / 1024.0, result.deviceBytesPer1000 / 1024.0,
                        result.liveObjectsPer1000);
            rows += std::string(rows.empty() ? "" : ",\n") + "    {\"chain\": " + bench::jsonString(chain) +
                    ", \"residentBytesPer1000\": " + bench::jsonNumber(result.residentBytesPer1000) +
                    ", \"deviceBytesPer1000\": " + bench::jsonNumber(result.deviceBytesPer1000) +
                    ", \"liveObjectsPer1000\": " + bench::jsonNumber(result.liveObjectsPer1000) +
                    ",\n     \"samples\": [\n" + samples + "\n     ]}";
        }
        const std::string json = bench::resultsHead({.program = "soak", .commandLine = bench::commandLineOf(argc, argv),
                                                     .device = {{"name", adapter.info().name}},
                                                     .validation = instance.validationEnabled()}) +
                                 "  \"frames\": " + std::to_string(options.frames) + ",\n  \"segment\": " +
                                 std::to_string(options.segment) + ",\n  \"chains\": [\n" + rows + "\n  ]\n}\n";
        bench::writeResults(options.output, json);
        std::printf("\nwritten to %s\n", options.output.c_str());
        return 0;
    });
}
