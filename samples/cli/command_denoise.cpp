// `hush denoise`: one or more chains over a folder of frames, with outputs, a
// quality table and report.json.
#include <cstdio>
#include <filesystem>
#include <optional>

#include <hush/core/error.hpp>
#include <hush/passes/chain_file.hpp>
#include <hush/rhi/rhi.hpp>
#include <hush/tracer/frame_io.hpp>

#include "command.hpp"
#include "denoise_job.hpp"
#include "output_folder.hpp"
#include "scene_argument.hpp"
#include "sweep_measure.hpp"
#include "sweep_result.hpp"

namespace hush::cli {
namespace {

std::string builtinList() {
    std::string list;
    for (const auto& name : passes::builtinChainNames()) list += (list.empty() ? "" : ", ") + name;
    return list;
}

const std::string& usage() {
    static const std::string text =
        "usage: hush denoise --in <folder> --out <folder> [--chain <list>] [--first <i>] [--frames <n>]\n"
        "                    [--no-exr] [--no-png] [--side-by-side] [--dump-graph] [--overwrite]\n"
        "                    [--reference <folder>] [--adapter <text>] [--budget-ms <ms> [--sweep <sweep.json>]]\n"
        "\n"
        "Runs denoising chains over the frames of <folder> (docs/frame-format.md), in index\n"
        "order. Writes <out>/<chain>/frame_<i>.exr (filtered radiance, layer 'color') and .png\n"
        "(the tonemapped display image, sRGB), the noisy input likewise under <out>/noisy/,\n"
        "and <out>/report.json; prints per-pass GPU times and, for frames that carry a\n"
        "'reference' layer, RMSE, relative MSE, PSNR and SSIM of the tonemapped images,\n"
        "plus the temporal error between consecutive outputs.\n"
        "\n"
        "options:\n"
        "  --chain <list>    comma-separated built-in chains (" + builtinList() + ") or chain files\n"
        "                    (docs/passes/chain-files.md); default: svgf\n"
        "  --in <folder>     the frames: hush's frame format, or Blender Cycles multilayer EXRs\n"
        "                    (read directly: docs/blender.md)\n"
        "  --reference <folder>  each frame's reference from the file of the same name there (its\n"
        "                    'color', or a Cycles file's Combined): e.g. the same frames rendered\n"
        "                    at many samples, so that quality is scored\n"
        "  --out <folder>    where outputs go: a new or empty folder, or an earlier hush run's\n"
        "                    (its stale outputs are removed; docs/reliability.md)\n"
        "  --overwrite       write into a folder that holds other files too\n"
        "  --first <i>       skip frames before index i\n"
        "  --frames <n>      at most n frames\n"
        "  --no-exr, --no-png  skip writing those outputs\n"
        "  --side-by-side    <out>/side_by_side/frame_<i>.png: noisy | chains | reference\n"
        "                    (the reference panel only where the frame has one)\n"
        "  --dump-graph      <out>/graph.<chain>.dot and .json: each compiled graph\n"
        "  --adapter <text>  use the first adapter whose name contains <text>\n"
        "  --budget-ms <ms> [--sweep <sweep.json>]\n"
        "                    instead of --chain: the configuration of that sweep (hush sweep) with\n"
        "                    the best quality whose GPU time is within <ms> on every source; says\n"
        "                    which and why. Without --sweep: the built-in chains at their defaults,\n"
        "                    measured first on these frames (some must carry a reference)\n"
        "\n"
        "node types for chain files:\n";
    static const std::string full = text + passes::describeChainNodes();
    return full;
}

// The chain file of the sweep's best configuration within the budget, saying why.
std::string chainWithinBudget(const std::string& sweepPath, double budgetMs) {
    const auto choice = chooseWithinBudget(readSweepJson(sweepPath), budgetMs);
    std::printf("hush denoise: budget %.3g ms: %s\n", budgetMs, choice.why.c_str());
    return (std::filesystem::path(sweepPath).parent_path() / "configs" / (choice.config + ".json")).string();
}

// Budget mode without a sweep: measures the built-in chains on the frames themselves
// (quickSweep), then denoises with the best one within the budget.
int runWithinBudget(DenoiseJobOptions options, const rhi::AdapterRequest& request, double budgetMs) {
    OutputFolder out(options.outFolder, "denoise", options.overwrite);
    {
        auto instance = rhi::Instance::create({});
        auto device = instance.requestAdapter(request).createDevice({.label = "hush denoise --budget-ms"});
        std::printf("hush denoise: budget %.3g ms without --sweep: measuring the built-in chains on the frames\n",
                    budgetMs);
        std::fflush(stdout);
        const auto choice = chooseWithinBudget(quickSweep(device, options.framePaths, out), budgetMs);
        std::printf("hush denoise: budget %.3g ms: %s\n", budgetMs, choice.why.c_str());
        options.chains = {choice.config};
    }
    return runDenoiseJobAndReport(options, request, &out);
}

int runDenoise(std::span<const std::string_view> args) {
    DenoiseJobOptions options;
    std::string in, chains = "svgf";
    rhi::AdapterRequest request;
    uint32_t first = 0, count = ~0u;
    bool dump = false;
    std::string sweep;
    double budgetMs = 0.0;
    for (size_t i = 0; i < args.size(); ++i) {
        std::string v;
        if (takeOption(args, i, "--in", v)) in = v;
        else if (takeOption(args, i, "--reference", v)) options.referenceFolder = v;
        else if (takeOption(args, i, "--budget-ms", v)) budgetMs = core::parseNumber(v, "--budget-ms", 1e-6, 1e9);
        else if (takeOption(args, i, "--sweep", v)) sweep = v;
        else if (takeOption(args, i, "--out", v)) options.outFolder = v;
        else if (takeOption(args, i, "--chain", v)) chains = v;
        else if (takeOption(args, i, "--first", v)) first = parseCount(v, "--first", 0, ~0u);
        else if (takeOption(args, i, "--frames", v)) count = parseCount(v, "--frames", 1, ~0u);
        else if (takeOption(args, i, "--adapter", v)) request.nameContains = v, request.nameFromEnvironment = false;
        else if (args[i] == "--no-exr") options.writeExr = false;
        else if (args[i] == "--no-png") options.writePng = false;
        else if (args[i] == "--side-by-side") options.sideBySide = true;
        else if (args[i] == "--dump-graph") dump = true;
        else if (args[i] == "--overwrite") options.overwrite = true;
        else unknownArgument("denoise", args[i]);
    }
    if (in.empty()) throw Error(ErrorKind::InvalidArgument, "hush denoise needs --in <folder of frames>");
    if (options.outFolder.empty()) throw Error(ErrorKind::InvalidArgument, "hush denoise needs --out <folder>");
    if (!sweep.empty() && budgetMs == 0.0)
        throw Error(ErrorKind::InvalidArgument, "--sweep is read by --budget-ms, which is missing");
    for (const auto& path : tracer::listFrames(in)) {
        const auto index = frameIndexOf(path);
        if (index >= first && options.framePaths.size() < count) options.framePaths.push_back(path);
    }
    if (options.framePaths.empty())
        throw Error(ErrorKind::NotFound, "'" + in + "' holds no frame with index >= " + std::to_string(first));
    options.dumpGraph = dump;
    if (budgetMs > 0.0 && sweep.empty()) return runWithinBudget(options, request, budgetMs);
    if (budgetMs > 0.0) chains = chainWithinBudget(sweep, budgetMs);
    options.chains = splitList(chains);
    if (options.chains.empty()) throw Error(ErrorKind::InvalidArgument, "--chain names no chain");
    return runDenoiseJobAndReport(options, request);
}

} // namespace

int runDenoiseJobAndReport(const DenoiseJobOptions& options, const rhi::AdapterRequest& request, OutputFolder* given) {
    // Everything a user can get wrong is found before the first frame is processed.
    std::optional<OutputFolder> own;
    if (!given) own.emplace(options.outFolder, "denoise", options.overwrite);
    OutputFolder& out = given ? *given : *own;
    checkSequence(options);
    auto instance = rhi::Instance::create({});
    auto adapter = instance.requestAdapter(request);
    auto device = adapter.createDevice({.label = "hush denoise"});
    std::printf("hush denoise: %zu frame(s) from %s, chains: ", options.framePaths.size(),
                std::filesystem::path(options.framePaths.front()).parent_path().string().c_str());
    for (size_t i = 0; i < options.chains.size(); ++i) std::printf("%s%s", i ? ", " : "", options.chains[i].c_str());
    std::printf(", on %s\n", adapter.info().name.c_str());
    std::fflush(stdout);
    const auto result = runDenoiseJob(device, options, out);
    std::fputs(formatReportTables(result).c_str(), stdout);
    core::writeFileAtomically(out.file("report.json"), reportJson(result, adapter.info().name));
    out.finish();
    for (const auto& w : result.warnings) std::fprintf(stderr, "hush: warning: %s\n", w.c_str());
    std::printf("\nwrote %s and the images under %s/\n", (out.path() / "report.json").string().c_str(),
                out.path().string().c_str());
    int code = kExitOk;
    for (const auto& c : result.chains)
        if (c.nonFiniteOutputs) {
            std::fprintf(stderr, "hush: error: chain '%s' produced %llu non-finite output value(s), first on frame %u "
                                 "(a setting outside what it handles? see report.json)\n",
                         c.name.c_str(), static_cast<unsigned long long>(c.nonFiniteOutputs), c.nonFiniteFrames.front());
            code = kExitFailed;
        }
    return code;
}

const Command& denoiseCommand() {
    static const Command command{"denoise", "denoise frames with chains (svgf, eaw, bmfr, mara, rdae, a chain file); report quality",
                                 usage(), runDenoise};
    return command;
}

} // namespace hush::cli
