// hush-bench-chains: the denoising chains (SVGF, EAW) as a whole.
//   timing   per-pass and per-frame GPU time over one 1-spp cornell frame at 640x360
//            and 1280x720, each pass's effective bandwidth as a fraction of the copy
//            roofline measured at the start of the same run (bandwidth_probe.hpp);
//   memory   transients with and without aliasing, histories;
//   quality  RMSE, PSNR, SSIM and temporal error of the noisy input and of each chain
//            on a short sequence of every built-in tracer scene.
// Prints markdown tables and writes bench-results/chains.json.
#include <algorithm>
#include <cstdio>
#include <string>
#include <string_view>

#include <hush/passes/chain_file.hpp>
#include <hush/core/error.hpp>

#include "chain_bench.hpp"

namespace hush::bench {
namespace {

using namespace chain_bench;
using namespace hush::rhi;

constexpr std::string_view kUsage =
    "usage: hush-bench-chains [options]\n"
    "\n"
    "Benchmarks denoising chains (by default the built-in svgf and eaw):\n"
    "  timing   one 1-spp frame of the cornell box per size, uploaded once, run\n"
    "           warm-up + N times; median GPU ms per pass (graph timestamps) and per\n"
    "           frame, CPU record ms, each pass's unique bytes read + written over its\n"
    "           median time and as a fraction of the roofline (an RGBA32F texture copy\n"
    "           at the same size, measured first in the same run);\n"
    "  memory   transient bytes with and without aliasing, history bytes;\n"
    "  quality  for every built-in scene a short sequence: RMSE, PSNR, SSIM against\n"
    "           the reference (tonemapped, means over the frames with one) and temporal\n"
    "           error (mean over consecutive frames) of the noisy input and each chain.\n"
    "\n"
    "options:\n"
    "  --chains L              chains: built-in names or chain files (default svgf,eaw)\n"
    "  --frames N              timed frames per chain and size (default 20)\n"
    "  --warmup N              untimed frames before them (default 5)\n"
    "  --sizes WxH,...         timing sizes (default 640x360,1280x720)\n"
    "  --probe-runs N          timed runs of the roofline probe (default 20)\n"
    "  --quality-size WxH|N    quality sequence size (default 128x128)\n"
    "  --quality-frames N      frames per scene (default 16)\n"
    "  --reference-frames L    frames with a reference, e.g. 7,15 (the default)\n"
    "  --reference-spp N       samples per pixel of the references (default 256)\n"
    "  --scenes L              scenes to score (default: every built-in scene)\n"
    "  --skip-timing           no timing and memory part\n"
    "  --skip-quality          no quality part\n"
    "  --quick                 a smoke test: 160x90 and 320x180, 1 + 3 frames; quality\n"
    "                          at 32x32, 6 frames, references on 2 and 5 at 16 spp\n"
    "                          (other options override these, wherever they stand)\n"
    "  --output PATH           JSON results (default bench-results/chains.json)\n"
    "  --adapter TEXT          the first adapter whose name contains TEXT (default:\n"
    "                          HUSH_ADAPTER)\n";

// "WxH", or "N" for N x N.
Extent2D parseSize(std::string_view flag, std::string_view text) {
    const auto size = core::parseSize(text, flag, 16384, /*square=*/true);
    return {size.width, size.height};
}

void applyQuick(Options& o) {
    o.sizes = {{160, 90}, {320, 180}};
    o.warmup = 1;
    o.frames = 3;
    o.probeRuns = 3;
    o.qualitySize = {32, 32};
    o.qualityFrames = 6;
    o.referenceFrames = {2, 5};
    o.referenceSpp = 16;
}

// Returns false when the program should just print the usage and stop.
bool parseOptions(int argc, char** argv, Options& o) {
    o.commandLine = commandLineOf(argc, argv);
    for (int i = 1; i < argc; ++i)
        if (std::string_view(argv[i]) == "--quick") applyQuick(o);
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--help" || arg == "-h") return false;
        auto value = [&]() -> std::string_view {
            if (i + 1 >= argc) throw Error(ErrorKind::InvalidArgument, std::string(arg) + " needs a value");
            return argv[++i];
        };
        if (arg == "--quick") {
            continue;   // applied above
        } else if (arg == "--chains") {
            o.chains = core::splitList(value());
        } else if (arg == "--frames") {
            o.frames = core::parseCount(value(), arg, 1);
        } else if (arg == "--warmup") {
            o.warmup = core::parseCount(value(), arg, 0);
        } else if (arg == "--sizes") {
            o.sizes.clear();
            for (const auto& item : core::splitList(value())) o.sizes.push_back(parseSize(arg, item));
        } else if (arg == "--probe-runs") {
            o.probeRuns = core::parseCount(value(), arg, 1);
        } else if (arg == "--quality-size") {
            o.qualitySize = parseSize(arg, value());
        } else if (arg == "--quality-frames") {
            o.qualityFrames = core::parseCount(value(), arg, 2);
        } else if (arg == "--reference-frames") {
            o.referenceFrames.clear();
            for (const auto& item : core::splitList(value())) o.referenceFrames.push_back(core::parseCount(item, arg, 0));
        } else if (arg == "--reference-spp") {
            o.referenceSpp = core::parseCount(value(), arg, 1);
        } else if (arg == "--scenes") {
            o.scenes = core::splitList(value());
        } else if (arg == "--skip-timing") {
            o.timing = false;
        } else if (arg == "--skip-quality") {
            o.quality = false;
        } else if (arg == "--output") {
            o.output = value();
        } else if (arg == "--adapter") {
            o.adapter.nameContains = value();
            o.adapter.nameFromEnvironment = false;
        } else {
            throw Error(ErrorKind::InvalidArgument,
                        "unknown argument '" + std::string(arg) + "' (see hush-bench-chains --help)");
        }
    }
    if (o.timing && o.sizes.empty()) throw Error(ErrorKind::InvalidArgument, "--sizes names no size");
    if (o.chains.empty()) throw Error(ErrorKind::InvalidArgument, "--chains names no chain");
    return true;
}

int run(const Options& options) {
    for (const auto& chain : options.chains) passes::makeChain(chain);   // a bad name or file fails now, not later
    Instance instance = Instance::create();
    Adapter adapter = instance.requestAdapter(options.adapter);
    const AdapterInfo& info = adapter.info();
    std::printf("[chains] adapter: %s (%s, %s); host CPU: %s\n", info.name.c_str(), info.driverName.c_str(),
                info.driverInfo.c_str(), core::hostCpuName().c_str());
    std::printf("[chains] validation %s\n",
                instance.validationEnabled() ? "on (slower: timings not representative)" : "off");
    Device device = adapter.createDevice({.label = "hush-bench-chains"});

    std::vector<Roofline> rooflines;
    std::vector<TimingResult> timings;
    ComputeRoofline compute;
    bool suspect = false;
    if (options.timing) {
        if (std::any_of(options.chains.begin(), options.chains.end(), countsArithmetic)) {
            std::printf("[chains] compute roofline (multiply-adds) ... ");
            std::fflush(stdout);
            compute = measureComputeRoofline(device, options.probeRuns);
            std::printf("%.2f GFLOP/s\n", compute.gflops);
            suspect = suspect || !compute.verified;
        }
        for (const Extent2D size : options.sizes) {
            std::printf("[chains] roofline at %ux%u ... ", size.width, size.height);
            std::fflush(stdout);
            rooflines.push_back(measureRoofline(device, size, options.probeRuns));
            std::printf("%.2f GB/s\n", rooflines.back().gbps);
            suspect = suspect || !rooflines.back().verified;
        }
        for (size_t s = 0; s < options.sizes.size(); ++s) {
            const Extent2D size = options.sizes[s];
            std::printf("[chains] rendering a 1-spp cornell frame at %ux%u ... ", size.width, size.height);
            std::fflush(stdout);
            const tracer::Frame frame = renderTimingFrame(size);
            std::printf("done\n");
            for (const auto& chain : options.chains) {
                std::printf("[chains] timing %s at %ux%u: %u + %u frames ... ", chain.c_str(), size.width,
                            size.height, options.warmup, options.frames);
                std::fflush(stdout);
                timings.push_back(measureChainTiming(device, chain, frame, rooflines[s], compute, options));
                std::printf("%.2f ms per frame\n", timings.back().totalGpuMs.median);
                suspect = suspect || timings.back().nonFiniteOutput != 0;
            }
        }
    }
    std::vector<QualityRow> quality;
    if (options.quality) quality = measureQuality(device, options);

    if (options.timing) {
        printRooflines(rooflines);
        printComputeRoofline(compute);
        for (const auto& t : timings)
            for (size_t s = 0; s < options.sizes.size(); ++s)
                if (options.sizes[s] == t.size) {
                    printTiming(t, rooflines[s]);
                    printArithmetic(t, compute);
                    printPaperShares(t);
                }
        printMemory(timings);
    }
    if (options.quality) printQuality(quality, options);
    writeResults(options.output,
                        toJson(options, info, instance.validationEnabled(), rooflines, compute, timings, quality));
    std::printf("\n[chains] wrote %s\n", options.output.c_str());
    if (suspect) {
        std::fprintf(stderr, "hush-bench-chains: a roofline copy did not verify or a chain produced non-finite "
                             "output; figures are suspect\n");
        return 1;
    }
    if (const size_t messages = instance.validationMessageCount(); messages != 0) {
        std::fprintf(stderr, "hush-bench-chains: %zu validation message(s)\n", messages);
        return 1;
    }
    return 0;
}

} // namespace
} // namespace hush::bench

int main(int argc, char** argv) {
    return hush::bench::guardedMain("hush-bench-chains", [&] {
        hush::bench::chain_bench::Options options;
        if (!hush::bench::parseOptions(argc, argv, options)) {
            std::printf("%.*s", int(hush::bench::kUsage.size()), hush::bench::kUsage.data());
            return 0;
        }
        return hush::bench::run(options);
    });
}
