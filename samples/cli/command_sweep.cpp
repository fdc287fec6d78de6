// `hush sweep`: the speed/accuracy trade, measured. Every configuration (chains x
// knob values) over every frame source (scenes x sizes, or a frames folder): GPU ms,
// device memory and quality; the Pareto front per source; a table, sweep.json,
// sweep.csv, a plot per source and report.html. Rendered frames are cached under
// <out>/frames/ and reused; sweep.json is rewritten after every configuration, so an
// interrupted sweep, run again with the same command, resumes where it stopped.
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <thread>

#include <hush/core/error.hpp>
#include <hush/core/run_environment.hpp>
#include <hush/rhi/rhi.hpp>
#include <hush/tracer/frame_io.hpp>

#include "command.hpp"
#include "denoise_job.hpp"
#include "output_folder.hpp"
#include "progress.hpp"
#include "render_sequence.hpp"
#include "scene_argument.hpp"
#include "sweep_config.hpp"
#include "sweep_measure.hpp"
#include "sweep_result.hpp"

namespace hush::cli {
namespace {

namespace fs = std::filesystem;

const std::string& usage() {
    static const std::string text =
        "usage: hush sweep [--scene <list> | --in <folder>] [--chain <list>] [--vary <knob>=<values>]...\n"
        "                  [--size <list>] [--frames <n>] [--reference-every <k>] [--reference-spp <n>]\n"
        "                  [--reference-pairs] [--lag] [--exposure <list>] [--metric <m>] [--out <folder>]\n"
        "                  [--overwrite] [--threads <n>] [--adapter <text>]\n"
        "\n"
        "Measures the speed/accuracy trade: runs every configuration (each chain with every\n"
        "combination of its knobs' values) over every frame source and reports GPU ms per frame\n"
        "(median), device memory and quality against the reference (RMSE, relative MSE, PSNR,\n"
        "SSIM on the tonemapped images; temporal error; ghosting: RMSE in pixels disoccluded in\n"
        "the last 4 frames over RMSE elsewhere; flicker, with --reference-pairs: temporal error\n"
        "over the references' own), and the Pareto front: the configurations no other beats on\n"
        "both time and quality. Writes\n"
        "  <out>/sweep.json, sweep.csv      every measurement, the fronts for every metric\n"
        "  <out>/plot-<source>.svg, .png    GPU ms against the metric, the front highlighted\n"
        "  <out>/report.html                plots, tables, crops: noisy | front | reference\n"
        "  <out>/configs/<config>.json      each configuration as a chain file\n"
        "  <out>/frames/<source>/           the rendered frames, reused by a later sweep\n"
        "Run again with the same arguments, an interrupted sweep resumes.\n"
        "\n"
        "options:\n"
        "  --scene <list>          scenes to render: " + sceneArgumentHelp() + "\n"
        "                          (default cornell)\n"
        "  --in <folder>           a folder of frames instead (docs/frame-format.md)\n"
        "  --chain <list>          built-in chains or chain files (default svgf,eaw)\n"
        "  --vary <chain>.<setting>=<values>\n"
        "                          a knob: a chain-file setting path and its values, as a list\n"
        "                          (16,32,64; true,false; aces,reinhard) or a whole-number range\n"
        "                          (1..5); repeatable; each chain runs every combination of its own\n"
        "  --size <list>           frame sizes for --scene, e.g. 128x128,256x256 (default 128x128)\n"
        "  --frames <n>            frames per source (default 16)\n"
        "  --reference-every <k>   a reference on every k-th frame, the last of each group (default 8)\n"
        "  --reference-spp <n>     samples per pixel of each reference (default 256)\n"
        "  --reference-pairs       also a reference on the frame before each scored one: measures\n"
        "                          flicker (temporal error over the references' own)\n"
        "  --lag                   also a reference on every frame of the second half, and each\n"
        "                          configuration run again with the light doubled from its first\n"
        "                          frame on: lag is the frames until its RMSE is within 10 % of\n"
        "                          a run with the light doubled throughout\n"
        "  --exposure <list>       also run every source with its radiance (and reference) times\n"
        "                          each value, e.g. 1e-6,1e-3,1,1e3,1e6, the tonemap scaled back:\n"
        "                          a scale-equivariant chain scores the same at every exposure;\n"
        "                          prints each configuration's RMSE over its RMSE at exposure 1\n"
        "  --metric <m>            the quality axis of plots and table: rmse, relmse, psnr, ssim,\n"
        "                          temporal (default ssim); sweep.json holds the fronts of all\n"
        "  --out <folder>          default: sweep\n"
        "  --overwrite             write into a folder that holds other files too\n"
        "  --threads <n>           rendering threads (default: every core)\n"
        "  --adapter <text>        use the first adapter whose name contains <text>\n";
    return text;
}

struct SweepOptions {
    std::vector<std::string> scenes{"cornell"}, chains{"svgf", "eaw"};
    std::string in, out = "sweep", metric = "ssim";
    std::vector<Knob> knobs;
    std::vector<core::Size2D> sizes{{128, 128}};
    std::vector<double> exposures{1.0};
    bool lag = false;
    SequenceRequest sequence;
    rhi::AdapterRequest adapter;
    bool overwrite = false;
    std::string commandLine;
};

SweepOptions parseOptions(std::span<const std::string_view> args) {
    SweepOptions o;
    o.sequence.frames = 16;
    o.sequence.referenceEvery = 8;
    o.sequence.settings.referenceSpp = 256;
    o.commandLine = "hush sweep";
    for (const auto a : args) o.commandLine += " " + std::string(a);
    for (size_t i = 0; i < args.size(); ++i) {
        std::string v;
        if (takeOption(args, i, "--scene", v)) o.scenes = splitList(v);
        else if (takeOption(args, i, "--in", v)) o.in = v;
        else if (takeOption(args, i, "--chain", v)) o.chains = splitList(v);
        else if (takeOption(args, i, "--vary", v)) o.knobs.push_back(parseKnob(v));
        else if (takeOption(args, i, "--size", v)) {
            o.sizes.clear();
            for (const auto& s : splitList(v)) o.sizes.push_back(parseSize(s, "--size", 4096, true));
        }
        else if (takeOption(args, i, "--frames", v)) o.sequence.frames = parseCount(v, "--frames", 2, 100000);
        else if (takeOption(args, i, "--reference-every", v)) o.sequence.referenceEvery = parseCount(v, "--reference-every", 1, 100000);
        else if (takeOption(args, i, "--reference-spp", v)) o.sequence.settings.referenceSpp = parseCount(v, "--reference-spp", 1, 1u << 20);
        else if (takeOption(args, i, "--metric", v)) o.metric = sweepMetric(v).key;
        else if (takeOption(args, i, "--exposure", v)) {
            o.exposures.clear();
            for (const auto& e : splitList(v)) o.exposures.push_back(core::parseNumber(e, "--exposure", 1e-12, 1e12));
        }
        else if (takeOption(args, i, "--out", v)) o.out = v;
        else if (takeOption(args, i, "--threads", v)) o.sequence.settings.threads = parseCount(v, "--threads", 1, 1024);
        else if (takeOption(args, i, "--adapter", v)) o.adapter.nameContains = v, o.adapter.nameFromEnvironment = false;
        else if (args[i] == "--overwrite") o.overwrite = true;
        else if (args[i] == "--reference-pairs") o.sequence.referencePairs = true;
        else if (args[i] == "--lag") o.lag = true;
        else unknownArgument("sweep", args[i]);
    }
    if (o.chains.empty()) throw Error(ErrorKind::InvalidArgument, "--chain names no chain");
    if (o.sequence.referenceEvery > o.sequence.frames)
        throw Error(ErrorKind::InvalidArgument, "--reference-every " + std::to_string(o.sequence.referenceEvery) +
                                                    " leaves no reference in " + std::to_string(o.sequence.frames) +
                                                    " frames: nothing to score");
    o.sequence.referenceOffset = o.sequence.referenceEvery - 1;   // the last frame of each group: it has history
    if (o.lag) o.sequence.referencesFrom = o.sequence.frames / 2;   // the lighting step, and every frame after it
    return o;
}

// One frame source: its key, and its frames (rendered into the cache when missing).
SourceFrames renderedSource(const SweepOptions& o, const std::string& sceneArgument, core::Size2D size,
                            OutputFolder& out) {
    const tracer::Renderer renderer(loadSceneArgument(sceneArgument));
    const std::string key = renderer.scene().name + "-" + std::to_string(size.width) + "x" + std::to_string(size.height);
    SequenceRequest request = o.sequence;
    request.settings.width = size.width;
    request.settings.height = size.height;
    // Scored against the pixel-filtered image, not the noisy frame's own pixel-centre
    // rays: temporal filters converge to the former (docs/sweep.md, `thin`).
    request.settings.antialiasedReference = true;
    request.settings.channels.clear();
    for (const auto channel : tracer::kAllChannels)
        if (channel != tracer::Channel::Reference) request.settings.channels.push_back(channel);
    // The cache's name holds everything that makes the frames differ.
    const fs::path folder = fs::path("frames") / (key + "-" + std::to_string(o.sequence.frames) + "f-ref" +
                                                  std::to_string(o.sequence.referenceEvery) + "x" +
                                                  std::to_string(o.sequence.settings.referenceSpp) + "spp-aa" +
                                                  (o.sequence.referencePairs ? "-pairs" : "") +
                                                  (o.lag ? "-lag" : ""));
    request.outFolder = (out.path() / folder).string();
    auto paths = fs::is_directory(request.outFolder) ? tracer::listFrames(request.outFolder) : std::vector<std::string>{};
    if (paths.size() != o.sequence.frames) {
        fs::create_directories(request.outFolder);
        std::printf("hush sweep: rendering %s: %u frames, a %u-spp anti-aliased reference on every %u-th\n", key.c_str(),
                    o.sequence.frames, o.sequence.settings.referenceSpp, o.sequence.referenceEvery);
        std::fflush(stdout);
        renderSequence(renderer, request);
        paths = tracer::listFrames(request.outFolder);
    } else {
        std::printf("hush sweep: %s: reusing the frames in %s\n", key.c_str(), request.outFolder.c_str());
    }
    for (const auto& p : paths) out.keep(folder / fs::path(p).filename());
    SourceFrames s{.paths = paths};
    for (uint32_t i = o.sequence.referenceOffset; i < o.sequence.frames; i += o.sequence.referenceEvery) s.scheduled.insert(i);
    if (o.lag) s.stepFrame = o.sequence.referencesFrom;
    s.source = {.key = key, .width = size.width, .height = size.height, .frames = uint32_t(paths.size())};
    s.source.description = "scene " + renderer.scene().name + ", " + std::to_string(size.width) + "x" +
                           std::to_string(size.height) + ", " + std::to_string(paths.size()) + " frames";
    return s;
}

// One source per exposure (the same frames): key "<key>-x<exposure>" unless the sweep
// has exposure 1 only.
std::vector<SourceFrames> withExposures(SourceFrames s, const std::vector<double>& exposures) {
    s.source.family = s.source.key;
    if (exposures.size() == 1 && exposures.front() == 1.0) return {s};
    std::vector<SourceFrames> variants;
    for (double e : exposures) {
        SourceFrames v = s;
        char suffix[32];
        std::snprintf(suffix, sizeof suffix, "-x%g", e);
        v.source.key += suffix;
        v.source.exposure = e;
        std::snprintf(suffix, sizeof suffix, ", radiance x %g", e);
        v.source.description += suffix;
        variants.push_back(std::move(v));
    }
    return variants;
}

std::vector<SourceFrames> frameSources(const SweepOptions& o, OutputFolder& out) {
    std::vector<SourceFrames> sources;
    if (!o.in.empty()) {
        SourceFrames s{.paths = tracer::listFrames(o.in)};
        if (s.paths.empty()) throw Error(ErrorKind::NotFound, "'" + o.in + "' holds no frame_<i>.exr");
        const auto info = tracer::readFrameInfo(s.paths.front());
        s.source = {.key = "frames-" + std::to_string(info.width) + "x" + std::to_string(info.height),
                    .description = o.in + ", " + std::to_string(info.width) + "x" + std::to_string(info.height) +
                                   ", " + std::to_string(s.paths.size()) + " frames",
                    .width = info.width, .height = info.height, .frames = uint32_t(s.paths.size())};
        return withExposures(std::move(s), o.exposures);
    }
    for (const auto& scene : o.scenes)
        for (const auto size : o.sizes) {
            for (auto& v : withExposures(renderedSource(o, scene, size, out), o.exposures)) sources.push_back(std::move(v));
            out.checkpoint();
        }
    return sources;
}

// The earlier run's result for this source and configuration, if its configuration
// was the same chain file; its images are kept.
const SweepPoint* resumable(const SweepResult& earlier, const SweepConfig& config, const SourceFrames& s,
                            const std::vector<uint32_t>& referenced, OutputFolder& out) {
    const SweepPoint* p = earlier.find(s.source.key, config.name);
    if (!p) return nullptr;
    const auto same = std::find_if(earlier.configs.begin(), earlier.configs.end(),
                                   [&](const SweepConfig& c) { return c.name == config.name && c.chainJson == config.chainJson; });
    if (same == earlier.configs.end()) return nullptr;
    const SweepReportFiles files;
    for (const std::string& folder : {config.name, std::string("noisy"), std::string("reference")}) {
        SweepSource shown = s.source;
        for (const auto frame : referenced) {
            shown.shownFrame = frame;
            if (!fs::exists(out.path() / files.image(shown, folder))) return nullptr;
            out.keep(files.image(shown, folder));
        }
    }
    return p;
}

// The configuration's chain file: configs/<name>.json, or at another exposure
// configs/x<exposure>/<name>.json with its tonemap scaled back (withExposure).
std::string configFile(const SweepConfig& config, double exposure, OutputFolder& out) {
    if (exposure == 1.0) return (out.path() / "configs" / (config.name + ".json")).string();
    char folder[32];
    std::snprintf(folder, sizeof folder, "x%g", exposure);
    const auto path = out.file(fs::path("configs") / folder / (config.name + ".json"));
    core::writeFileAtomically(path, withExposure(config.chainJson, exposure) + "\n");
    return path.string();
}

void writeReport(const SweepResult& result, OutputFolder& out) {
    const SweepReportFiles files;
    for (const auto& s : result.sources) {
        const auto svg = out.file(files.plotSvg(s)), png = out.file(files.plotPng(s));
        core::writeAtomically(svg, [&](const std::string& svgTemporary) {
            core::writeAtomically(png, [&](const std::string& pngTemporary) {
                writeSweepPlot(result, s, svgTemporary, pngTemporary);
            });
        });
    }
    core::writeFileAtomically(out.file("report.html"), sweepHtml(result, files));
    core::writeFileAtomically(out.file("sweep.csv"), sweepCsv(result));
}

int runSweep(std::span<const std::string_view> args) {
    const SweepOptions o = parseOptions(args);
    SweepResult result;
    result.metric = o.metric;
    result.configs = expandConfigs(o.chains, o.knobs);   // every knob checked before any work
    OutputFolder out(o.out, "sweep", o.overwrite);
    SweepResult earlier;
    if (fs::exists(out.path() / "sweep.json")) earlier = readSweepJson((out.path() / "sweep.json").string());
    for (const auto& c : result.configs)
        core::writeFileAtomically(out.file(fs::path("configs") / (c.name + ".json")), c.chainJson + "\n");
    tracer::setFrameIoThreadCount(std::max(1u, std::thread::hardware_concurrency()));

    auto instance = rhi::Instance::create({});
    auto adapter = instance.requestAdapter(o.adapter);
    auto device = adapter.createDevice({.label = "hush sweep"});
    result.environment = core::toJson({.program = "sweep", .commandLine = o.commandLine,
                                       .device = {{"name", adapter.info().name}}});
    const auto sources = frameSources(o, out);
    std::printf("hush sweep: %zu configuration(s) x %zu source(s) on %s -> %s\n", result.configs.size(),
                sources.size(), adapter.info().name.c_str(), out.path().string().c_str());
    std::fflush(stdout);

    if (!earlier.points.empty())
        std::printf("hush sweep: resuming: an earlier run in %s measured %zu configuration(s) x source(s)\n",
                    out.path().string().c_str(), earlier.points.size());
    ProgressLine progress("sweep");
    const size_t total = result.configs.size() * sources.size();
    size_t done = 0, reused = 0;
    for (const auto& s : sources) {
        result.sources.push_back(s.source);
        // Read from the frames' headers once per source, not once per configuration.
        const auto referenced = scoredFrames(s.paths);
        result.sources.back().shownFrame = referenced.back();
        for (const auto& config : result.configs) {
            const auto chainFile = configFile(config, s.source.exposure, out);
            if (const SweepPoint* p = resumable(earlier, config, s, referenced, out)) {
                ++reused;
                result.points.push_back(*p);
                const auto es = std::find_if(earlier.sources.begin(), earlier.sources.end(),
                                             [&](const SweepSource& e) { return e.key == s.source.key; });
                if (es != earlier.sources.end()) result.sources.back().noisy = es->noisy;
            } else {
                result.points.push_back(measure(device, s, chainFile, config.name, out, result.sources.back().noisy));
            }
            core::writeFileAtomically(out.file("sweep.json"), sweepJson(result));
            out.checkpoint();
            ++done;
            progress.update(double(done) / double(total), s.source.key + " " + config.name + " (" +
                                                              std::to_string(done) + "/" + std::to_string(total) + ")");
        }
    }
    progress.finish("done: " + std::to_string(total - reused) + " run(s) measured, " + std::to_string(reused) +
                    " reused from an earlier run");
    result.complete = true;
    writeReport(result, out);
    core::writeFileAtomically(out.file("sweep.json"), sweepJson(result));
    out.finish();
    std::fputs(sweepTable(result).c_str(), stdout);
    for (const auto& s : result.sources) std::fputs(sweepTextPlot(result, s).c_str(), stdout);
    std::fputs(sweepExposureTable(result).c_str(), stdout);
    std::printf("\nwrote %s/report.html, sweep.json, sweep.csv and the plots\n", out.path().string().c_str());
    int code = kExitOk;
    for (const auto& p : result.points)
        if (p.nonFiniteOutputs) {
            std::fprintf(stderr, "hush: error: %s on %s produced %llu non-finite output value(s)\n", p.config.c_str(),
                         p.source.c_str(), static_cast<unsigned long long>(p.nonFiniteOutputs));
            code = kExitFailed;
        }
    return code;
}

} // namespace

const Command& sweepCommand() {
    static const Command command{"sweep", "measure the speed/accuracy trade of chains and settings: table, Pareto "
                                          "front, plot, report.html", usage(), runSweep};
    return command;
}

} // namespace hush::cli
