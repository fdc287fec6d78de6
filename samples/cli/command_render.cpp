// `hush render`: the tracer's frames of a scene's camera path, written in the frame
// format (docs/frame-format.md), with progress and an estimate of the time left.
#include <cstdio>
#include <filesystem>
#include <thread>

#include <hush/core/error.hpp>
#include <hush/tracer/frame_io.hpp>
#include <hush/tracer/renderer.hpp>

#include "command.hpp"
#include "output_folder.hpp"
#include "render_sequence.hpp"
#include "scene_argument.hpp"

namespace hush::cli {
namespace {

const std::string& usage() {
    static const std::string text =
        "usage: hush render [--scene <scene>] [--frames <n>] [--first <i>] [--size <W>x<H>]\n"
        "                   [--reference-spp <n>] [--reference-every <k>] [--channels <list>]\n"
        "                   [--bounces <n>] [--seed <n>] [--jitter] [--antialiased-reference]\n"
        "                   [--threads <n>] [--overwrite]\n"
        "                   --out <folder>\n"
        "\n"
        "Renders frames of the scene's camera path with the path tracer and writes each\n"
        "as <folder>/frame_<i>.exr (docs/frame-format.md): a 1-sample noisy estimate, a\n"
        "noise-free G-buffer, motion vectors, and references.\n"
        "\n"
        "options:\n"
        "  --scene <scene>        " + sceneArgumentHelp() + "\n"
        "  --frames <n>           how many frames (default 16)\n"
        "  --first <i>            index of the first frame (default 0)\n"
        "  --size <W>x<H>         image size (default 256x256)\n"
        "  --reference-spp <n>    samples per pixel of the reference (default 1024; 0: none)\n"
        "  --reference-every <k>  a reference on every k-th frame only (default 1)\n"
        "  --channels <list>      comma-separated channels, or 'all' (default: color, direct,\n"
        "                         indirect, emission, albedo, normal, position, depth, motion,\n"
        "                         meshid, roughness, specular: what the svgf and eaw chains read);\n"
        "                         matte or glossy switch on Mara et al.'s factored terms\n"
        "  --bounces <n>          indirect bounces after the primary hit (default 1)\n"
        "  --seed <n>             sampling seed (default 1); same seed, same frames\n"
        "  --jitter               per-frame subpixel jitter of the primary rays (recorded)\n"
        "  --antialiased-reference  each reference sample through a random point of its pixel\n"
        "                         (a box filter), not the noisy frame's own primary ray\n"
        "  --threads <n>          rendering threads (default: every core)\n"
        "  --out <folder>         where the frames go: a new or empty folder, or an earlier hush\n"
        "                         run's (its stale frames are removed)\n"
        "  --overwrite            write into a folder that holds other files too\n";
    return text;
}

int runRender(std::span<const std::string_view> args) {
    std::string sceneName = "cornell", outFolder;
    uint32_t frames = 16, first = 0, referenceEvery = 1;
    bool overwrite = false;
    tracer::RenderSettings settings;
    settings.channels = {tracer::Channel::Color,  tracer::Channel::Albedo,   tracer::Channel::Normal,
                         tracer::Channel::Position, tracer::Channel::Depth,  tracer::Channel::Motion,
                         tracer::Channel::MeshId, tracer::Channel::Roughness, tracer::Channel::Specular,
                         tracer::Channel::Direct, tracer::Channel::Indirect, tracer::Channel::Emission};
    for (size_t i = 0; i < args.size(); ++i) {
        std::string v;
        if (takeOption(args, i, "--scene", v)) sceneName = v;
        else if (takeOption(args, i, "--frames", v)) frames = parseCount(v, "--frames", 1, 100000);
        else if (takeOption(args, i, "--first", v)) first = parseCount(v, "--first", 0, 1000000);
        else if (takeOption(args, i, "--size", v)) {
            const auto size = parseSize(v, "--size");
            settings.width = size.width;
            settings.height = size.height;
        }
        else if (takeOption(args, i, "--reference-spp", v)) settings.referenceSpp = parseCount(v, "--reference-spp", 0, 1u << 20);
        else if (takeOption(args, i, "--reference-every", v)) referenceEvery = parseCount(v, "--reference-every", 1, 100000);
        else if (takeOption(args, i, "--channels", v)) settings.channels = tracer::parseChannelList(v);
        else if (takeOption(args, i, "--bounces", v)) settings.bounces = parseCount(v, "--bounces", 0, 64);
        else if (takeOption(args, i, "--seed", v)) settings.seed = parseCount(v, "--seed", 0, ~0u);
        else if (takeOption(args, i, "--threads", v)) settings.threads = parseCount(v, "--threads", 1, 1024);
        else if (takeOption(args, i, "--out", v)) outFolder = v;
        else if (args[i] == "--jitter") settings.jitter = true;
        else if (args[i] == "--antialiased-reference") settings.antialiasedReference = true;
        else if (args[i] == "--overwrite") overwrite = true;
        else unknownArgument("render", args[i]);
    }
    if (outFolder.empty()) throw Error(ErrorKind::InvalidArgument, "hush render needs --out <folder>");
    for (auto c : settings.channels)
        if (c == tracer::Channel::Reference) settings.referenceSpp = std::max(settings.referenceSpp, 1u);
    OutputFolder folder(outFolder, "render", overwrite);
    // OpenEXR compresses in parallel only through its process-wide pool.
    tracer::setFrameIoThreadCount(std::max(1u, std::thread::hardware_concurrency()));

    const tracer::Renderer renderer(loadSceneArgument(sceneName));
    std::printf("hush render: scene '%s', camera path '%s', %u frames from %u at %ux%u, %u bounce%s, reference %u spp %s\n",
                renderer.scene().name.c_str(), renderer.scene().camera.name.c_str(), frames, first, settings.width,
                settings.height, settings.bounces, settings.bounces == 1 ? "" : "s", settings.referenceSpp,
                settings.referenceSpp ? ("every " + std::to_string(referenceEvery) + " frame(s)").c_str() : "(none)");
    std::fflush(stdout);

    renderSequence(renderer, {.settings = settings,
                              .first = first,
                              .frames = frames,
                              .referenceEvery = referenceEvery,
                              .outFolder = outFolder});
    for (uint32_t i = first; i < first + frames; ++i)
        folder.keep(std::filesystem::path(tracer::framePath(outFolder, i)).filename());
    folder.finish();
    return kExitOk;
}

} // namespace

const Command& renderCommand() {
    static const Command command{"render", "render frames of a scene with the path tracer (EXR frames)", usage(), runRender};
    return command;
}

} // namespace hush::cli
