// `hush demo`: the README's main job. Renders the default scene's camera path with
// the path tracer, denoises it with EAW, SVGF and BMFR, and reports time and quality side
// by side: images, a side-by-side strip per scored frame, tables and report.json.
#include <cstdio>
#include <filesystem>
#include <thread>

#include <hush/core/error.hpp>
#include <hush/tracer/frame_io.hpp>

#include "command.hpp"
#include "denoise_job.hpp"
#include "output_folder.hpp"
#include "render_sequence.hpp"
#include "scene_argument.hpp"

namespace hush::cli {
namespace {

// Every method hush implements, the baseline first.
constexpr std::string_view kDemoChains = "eaw,svgf,bmfr,mara,rdae";

struct DemoDefaults {
    static constexpr uint32_t frames = 32, referenceEvery = 8, referenceSpp = 512, size = 256;
};

const std::string& usage() {
    static const std::string text =
        "usage: hush demo [--out <folder>] [--scene <scene>] [--size <W>x<H>] [--frames <n>]\n"
        "                 [--reference-every <k>] [--reference-spp <n>] [--chain <list>]\n"
        "                 [--reuse-frames] [--threads <n>] [--adapter <text>]\n"
        "\n"
        "The main job: renders the scene's camera path (1 sample per pixel, split into direct\n"
        "and indirect light and into Mara et al.'s matte and glossy terms, with a G-buffer\n"
        "and motion; an anti-aliased reference, each sample through a random point of its\n"
        "pixel, on every k-th frame),\n"
        "writes the frames to <out>/frames/, denoises them with each chain, and writes\n"
        "  <out>/<chain>/frame_<i>.exr and .png    filtered radiance and display image\n"
        "  <out>/side_by_side/frame_<i>.png        noisy | chains | reference, scored frames\n"
        "  <out>/report.json                       per-pass GPU ms, RMSE, SSIM, temporal error\n"
        "  <out>/graph.<chain>.dot and .json       each compiled graph\n"
        "\n"
        "options:\n"
        "  --out <folder>          default: out\n"
        "  --scene <scene>         " + sceneArgumentHelp() + "\n"
        "  --size <W>x<H>          default 256x256\n"
        "  --frames <n>            default 32\n"
        "  --reference-every <k>   default 8 (frames 7, 15, 23, 31 are scored)\n"
        "  --reference-spp <n>     samples per pixel of each reference (default 512)\n"
        "  --chain <list>          default: " + std::string(kDemoChains) + " (the strip follows this order)\n"
        "  --reuse-frames          denoise the frames already in <out>/frames/ instead of rendering\n"
        "  --overwrite             write into an <out> that holds files no hush run wrote\n"
        "  --threads <n>           rendering threads (default: every core)\n"
        "  --adapter <text>        use the first adapter whose name contains <text>\n";
    return text;
}

int runDemo(std::span<const std::string_view> args) {
    std::string sceneName = "cornell", out = "out", chains(kDemoChains);
    SequenceRequest sequence;
    sequence.frames = DemoDefaults::frames;
    sequence.referenceEvery = DemoDefaults::referenceEvery;
    auto& settings = sequence.settings;
    settings.width = settings.height = DemoDefaults::size;
    settings.referenceSpp = DemoDefaults::referenceSpp;
    settings.antialiasedReference = true;   // the pixel-filtered image (docs/sweep.md)
    // Every layer but the reference (added on the scored frames). Asking for Mara et
    // al.'s matte and glossy terms makes `direct` their low-noise direct light, for
    // every chain alike (docs/tracer.md).
    settings.channels.clear();
    for (const auto channel : tracer::kAllChannels)
        if (channel != tracer::Channel::Reference) settings.channels.push_back(channel);
    rhi::AdapterRequest request;
    bool reuse = false, overwrite = false;
    for (size_t i = 0; i < args.size(); ++i) {
        std::string v;
        if (takeOption(args, i, "--out", v)) out = v;
        else if (takeOption(args, i, "--scene", v)) sceneName = v;
        else if (takeOption(args, i, "--size", v)) {
            const auto size = parseSize(v, "--size");
            settings.width = size.width;
            settings.height = size.height;
        }
        else if (takeOption(args, i, "--frames", v)) sequence.frames = parseCount(v, "--frames", 1, 100000);
        else if (takeOption(args, i, "--reference-every", v)) sequence.referenceEvery = parseCount(v, "--reference-every", 1, 100000);
        else if (takeOption(args, i, "--reference-spp", v)) settings.referenceSpp = parseCount(v, "--reference-spp", 1, 1u << 20);
        else if (takeOption(args, i, "--chain", v)) chains = v;
        else if (takeOption(args, i, "--threads", v)) settings.threads = parseCount(v, "--threads", 1, 1024);
        else if (takeOption(args, i, "--adapter", v)) request.nameContains = v, request.nameFromEnvironment = false;
        else if (args[i] == "--reuse-frames") reuse = true;
        else if (args[i] == "--overwrite") overwrite = true;
        else unknownArgument("demo", args[i]);
    }
    // Score the last frame of each group, where the temporal filters have history.
    sequence.referenceOffset = sequence.referenceEvery - 1;
    OutputFolder folder(out, "demo", overwrite);
    sequence.outFolder = (folder.path() / "frames").string();
    std::filesystem::create_directories(sequence.outFolder);
    tracer::setFrameIoThreadCount(std::max(1u, std::thread::hardware_concurrency()));

    if (!reuse) {
        const tracer::Renderer renderer(loadSceneArgument(sceneName));
        std::printf("hush demo: scene '%s', %u frames at %ux%u, reference %u spp on every %u-th frame -> %s\n",
                    renderer.scene().name.c_str(), sequence.frames, settings.width, settings.height,
                    settings.referenceSpp, sequence.referenceEvery, sequence.outFolder.c_str());
        std::fflush(stdout);
        renderSequence(renderer, sequence);
    }
    DenoiseJobOptions options;
    options.outFolder = out;
    options.sideBySide = true;
    options.dumpGraph = true;
    options.chains = splitList(chains);
    options.framePaths = tracer::listFrames(sequence.outFolder);
    for (const auto& frame : options.framePaths)   // inputs this run made (or reuses): not stale
        folder.keep(std::filesystem::path("frames") / std::filesystem::path(frame).filename());
    return runDenoiseJobAndReport(options, request, &folder);
}

} // namespace

const Command& demoCommand() {
    static const Command command{"demo", "the main job: render the default scene, denoise it with every method, "
                                         "report time and quality", usage(), runDemo};
    return command;
}

} // namespace hush::cli
