#include "denoise_job.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <set>

#include <hush/passes/chain_file.hpp>
#include <hush/passes/common/tonemap.hpp>
#include <hush/core/error.hpp>
#include <hush/tracer/frame_io.hpp>

#include "denoise_run.hpp"
#include "frame_upload.hpp"
#include "output_folder.hpp"
#include "png_file.hpp"
#include "progress.hpp"
#include "temporal_artifacts.hpp"

namespace hush::cli {

uint32_t frameIndexOf(const std::string& path) {
    const auto stem = std::filesystem::path(path).stem().string();
    return uint32_t(std::stoul(stem.substr(stem.find('_') + 1)));
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

namespace {

// Display values of an HDR image with the chains' default tonemap, for the noisy
// baseline and the reference (the chains tonemap on the GPU with the same curve).
RgbaImage tonemapped(const RgbaImage& hdr, float exposure) {
    RgbaImage out = hdr;
    const passes::TonemapSettings settings{.exposure = 1.0f / exposure};
    for (size_t i = 0; i < size_t(out.width) * out.height; ++i) passes::tonemap(settings, &out.rgba[i * 4]);
    return out;
}

// Every radiance layer times `exposure` (the G-buffer stays): an exposure sweep's input.
void scaleRadiance(tracer::Frame& frame, float exposure) {
    using tracer::Channel;
    for (const Channel c : {Channel::Color, Channel::Direct, Channel::Indirect, Channel::Emission, Channel::Matte,
                            Channel::Glossy, Channel::Reference})
        if (const auto it = frame.channels.find(c); it != frame.channels.end())
            for (float& v : it->second.pixels) v *= exposure;
}

// The noisy radiance: `color`, else direct + indirect.
RgbaImage noisyRadiance(const tracer::Frame& frame) {
    if (frame.has(tracer::Channel::Color)) return toRgba(frame.get(tracer::Channel::Color));
    if (frame.has(tracer::Channel::Direct) && frame.has(tracer::Channel::Indirect)) {
        RgbaImage sum = toRgba(frame.get(tracer::Channel::Direct));
        const RgbaImage indirect = toRgba(frame.get(tracer::Channel::Indirect));
        for (size_t i = 0; i < sum.rgba.size(); ++i)
            if (i % 4 != 3) sum.rgba[i] += indirect.rgba[i];
        return sum;
    }
    throw Error(ErrorKind::NotFound, "frame " + std::to_string(frame.index) +
                                         " has neither 'color' nor 'direct' + 'indirect': nothing to denoise");
}

std::string frameName(uint32_t index, const char* extension) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04u.%s", index, extension);
    return name;
}

void writePngOutput(const DenoiseJobOptions& o, OutputFolder& out, const std::string& folder, uint32_t index,
                    const RgbaImage& display) {
    writePng(out.file(std::filesystem::path(o.outputPrefix) / folder / frameName(index, "png")).string(),
             display.width, display.height, encodeSrgb8(display));
}

void writeOutputs(const DenoiseJobOptions& o, OutputFolder& out, const std::string& chain,
                  const tracer::Frame& source, const RgbaImage& radiance, const RgbaImage& display) {
    const std::filesystem::path folder = std::filesystem::path(o.outputPrefix) / chain;
    if (o.writeExr) {
        tracer::Frame frame;
        frame.width = source.width, frame.height = source.height, frame.index = source.index;
        frame.scene = source.scene;
        frame.camera = source.camera, frame.previousCamera = source.previousCamera;
        auto& color = frame.add(tracer::Channel::Color);
        for (size_t i = 0; i < size_t(frame.width) * frame.height; ++i)
            for (size_t c = 0; c < 3; ++c) color.pixels[i * 3 + c] = radiance.rgba[i * 4 + c];
        tracer::writeFrame(frame, out.file(folder / frameName(source.index, "exr")).string());
    }
    if (o.writePng && (!o.pngScoredOnly || source.has(tracer::Channel::Reference)))
        writePngOutput(o, out, chain, source.index, display);
}

// Metrics degrade, never abort: a reference (or output) without one finite pixel leaves
// the frame unscored, with a warning, instead of ending the job.
template <class F> bool scoreOrWarn(DenoiseJobResult& result, const std::string& what, F&& score) {
    try {
        score();
        return true;
    } catch (const Error& e) {
        if (e.kind() != ErrorKind::InvalidArgument) throw;
        result.warnings.push_back(what + " left unscored: " + e.what());
        return false;
    }
}

// Ghosting (with a disocclusion mask) and flicker (with last frame's reference) of
// every chain's display on a scored frame.
void scoreTemporalArtifacts(DenoiseJobResult& result, const std::vector<RgbaImage>& display,
                            const std::vector<RgbaImage>& previous, const RgbaImage& reference,
                            const RgbaImage* previousReference, const std::vector<uint8_t>& recent,
                            passes::MetricsEvaluator& metrics) {
    double referenceChange = 0.0;
    if (previousReference) referenceChange = metrics.temporalError(reference.rgba, previousReference->rgba);
    for (size_t c = 0; c < result.chains.size(); ++c) {
        auto& chain = result.chains[c];
        if (!recent.empty()) {
            const double near = maskedRmse(display[c], reference, recent, true);
            const double far = maskedRmse(display[c], reference, recent, false);
            if (near >= 0.0 && far > 0.0) chain.ghosting.push_back(near / far);
        }
        if (referenceChange > 0.0 && !previous[c].rgba.empty())
            chain.flicker.push_back(metrics.temporalError(display[c].rgba, previous[c].rgba) / referenceChange);
    }
}

// Each chain writes <out>/<name>/: a name must be a plain folder name (chain files
// are checked when read; built-in names are), not one the job itself writes, and
// not another chain's.
void checkOutputNames(const std::vector<ChainResult>& chains, const std::vector<std::string>& given) {
    static constexpr std::string_view kReserved[] = {"noisy", "side_by_side", "frames", "graph"};
    for (size_t i = 1; i < chains.size(); ++i) {
        const std::string& name = chains[i].name;
        const std::string& from = given[i - 1];
        if (!passes::isValidChainName(name))
            throw Error(ErrorKind::InvalidArgument, "chain '" + from + "' is named '" + name + "', not a valid chain "
                                                    "name (" + std::string(passes::kChainNameRule) + ")");
        if (std::find(std::begin(kReserved), std::end(kReserved), name) != std::end(kReserved))
            throw Error(ErrorKind::InvalidArgument, "chain '" + from + "' is named '" + name + "', which the output "
                                                    "folder uses for something else; give the chain file another "
                                                    "\"name\"");
        for (size_t j = 1; j < i; ++j)
            if (chains[j].name == name)
                throw Error(ErrorKind::InvalidArgument,
                            "two chains are named '" + name + "' ('" + given[j - 1] + "' and '" + from +
                                "'): each writes <out>/" + name + "/; give one of them a chain file with another "
                                "\"name\"");
    }
}

std::string referencePath(const DenoiseJobOptions& o, const std::string& framePath) {
    return (std::filesystem::path(o.referenceFolder) / std::filesystem::path(framePath).filename()).string();
}

void checkReference(const DenoiseJobOptions& o, const std::string& framePath, const tracer::FrameFileInfo& frame,
                    std::vector<std::string>& problems) {
    const std::string path = referencePath(o, framePath);
    try {
        const auto info = tracer::readFrameInfo(path);
        if (info.width != frame.width || info.height != frame.height)
            problems.push_back(path + ": the reference is " + std::to_string(info.width) + "x" +
                               std::to_string(info.height) + ", its frame " + std::to_string(frame.width) + "x" +
                               std::to_string(frame.height));
        else if (std::find(info.layers.begin(), info.layers.end(), tracer::Channel::Color) == info.layers.end())
            problems.push_back(path + ": no 'color' layer (or Cycles Combined pass) to take the reference from");
    } catch (const Error& e) {
        problems.push_back(std::string("--reference: ") + e.what());
    }
}

// The reference from --reference's folder: its 'color' becomes the frame's reference.
void addReference(const DenoiseJobOptions& o, const std::string& framePath, tracer::Frame& frame) {
    tracer::Frame reference = tracer::readFrame(referencePath(o, framePath),
                                                {.channels = {tracer::Channel::Color}, .expectedWidth = frame.width,
                                                 .expectedHeight = frame.height});
    frame.channels[tracer::Channel::Reference] = std::move(reference.channels.at(tracer::Channel::Color));
}

} // namespace

void checkSequence(const DenoiseJobOptions& o) {
    if (o.framePaths.empty()) throw Error(ErrorKind::InvalidArgument, "no frames to denoise");
    std::vector<std::string> problems;
    const auto first = tracer::readFrameInfo(o.framePaths.front());
    // The layers every chain reads (emission may be absent: nothing to take out).
    std::set<tracer::Channel> needed;
    for (const auto& name : o.chains)
        for (const auto c : passes::makeChain(name)->inputs())
            if (c != passes::InputChannel::Emission) needed.insert(frames::layerOf(c));
    uint32_t previousIndex = 0;
    for (size_t f = 0; f < o.framePaths.size(); ++f) {
        tracer::FrameFileInfo info;
        try {
            info = tracer::readFrameInfo(o.framePaths[f]);
        } catch (const Error& e) {
            problems.push_back(e.what());
            continue;
        }
        const std::string where = o.framePaths[f] + ": ";
        if (info.width != first.width || info.height != first.height)
            problems.push_back(where + std::to_string(info.width) + "x" + std::to_string(info.height) +
                               ", the sequence starts at " + std::to_string(first.width) + "x" +
                               std::to_string(first.height));
        for (const auto layer : needed)
            if (std::find(info.layers.begin(), info.layers.end(), layer) == info.layers.end())
                problems.push_back(where + "no '" + std::string(tracer::channelInfo(layer).name) +
                                   "' layer, which a chain reads (hush render --channels all writes every layer)");
        if (!o.referenceFolder.empty()) checkReference(o, o.framePaths[f], info, problems);
        const uint32_t index = frameIndexOf(o.framePaths[f]);
        if (f > 0 && index <= previousIndex)
            problems.push_back(where + "index " + std::to_string(index) + " does not follow " +
                               std::to_string(previousIndex));
        previousIndex = index;
    }
    if (problems.empty()) return;
    std::string message = std::to_string(problems.size()) + " problem(s) in the frames, found before any work:";
    for (const auto& p : problems) message += "\n  " + p;
    throw Error(ErrorKind::InvalidArgument, message);
}

DenoiseJobResult runDenoiseJob(const rhi::Device& device, const DenoiseJobOptions& o, OutputFolder& out) {
    if (o.framePaths.empty()) throw Error(ErrorKind::InvalidArgument, "no frames to denoise");
    const auto start = std::chrono::steady_clock::now();
    const auto info = tracer::readFrameInfo(o.framePaths.front());
    const rhi::Extent2D size{info.width, info.height};

    DenoiseJobResult result;
    result.width = size.width, result.height = size.height;
    result.chains.push_back({.name = "noisy"});
    std::vector<std::unique_ptr<DenoiseRun>> runs;
    for (const auto& name : o.chains) {
        runs.push_back(std::make_unique<DenoiseRun>(device, passes::makeChain(name), size, frames::channelsOf(info.layers)));
        result.chains.push_back({.name = runs.back()->chain().name()});
    }
    checkOutputNames(result.chains, o.chains);
    if (o.dumpGraph)
        for (auto& run : runs) {
            const std::string stem = "graph." + run->chain().name();
            out.file(stem + ".dot");
            out.file(stem + ".json");
            run->graph().writeDump((out.path() / stem).string());
        }

    passes::MetricsEvaluator metrics(device, size);
    std::vector<RgbaImage> previous(result.chains.size());
    ProgressLine progress("denoise");
    uint32_t previousIndex = 0;
    DisocclusionAge ages;
    RgbaImage previousReference;   // last frame's, when it had one
    for (size_t f = 0; f < o.framePaths.size(); ++f) {
        auto frame = tracer::readFrame(o.framePaths[f], {.requireChannels = false,
                                                         .expectedWidth = size.width,
                                                         .expectedHeight = size.height});
        if (!o.referenceFolder.empty()) addReference(o, o.framePaths[f], frame);
        if (o.exposure != 1.0f) scaleRadiance(frame, o.exposure);
        if (frame.index >= o.stepFrame) scaleRadiance(frame, o.stepExposure);
        // A gap in the indices is a cut: no history may carry across it.
        const bool gap = f > 0 && frame.index != previousIndex + 1;
        if (gap) {
            for (auto& run : runs) run->resetHistory();
            result.warnings.push_back("frames " + std::to_string(previousIndex) + " and " +
                                      std::to_string(frame.index) + " are not consecutive: histories reset there");
        }
        previousIndex = frame.index;
        std::vector<RgbaImage> display(result.chains.size());
        const RgbaImage noisy = noisyRadiance(frame);
        display[0] = tonemapped(noisy, o.exposure);
        writeOutputs(o, out, "noisy", frame, noisy, display[0]);
        for (size_t c = 0; c < runs.size(); ++c) {
            auto denoised = runs[c]->process(frame);
            auto& chain = result.chains[c + 1];
            chain.sanitizedPixels += denoised.sanitized;
            const uint64_t bad = frames::countNonFinite(denoised.radiance.rgba) + frames::countNonFinite(denoised.display.rgba);
            chain.nonFiniteOutputs += bad;
            if (bad) chain.nonFiniteFrames.push_back(frame.index);
            writeOutputs(o, out, chain.name, frame, denoised.radiance, denoised.display);
            display[c + 1] = std::move(denoised.display);
        }
        const bool scored = frame.has(tracer::Channel::Reference);
        const bool hasGeometry = frame.has(tracer::Channel::Motion) && frame.has(tracer::Channel::MeshId) &&
                                 frame.has(tracer::Channel::Depth);
        if (hasGeometry) ages.update(frame, f == 0 || gap);
        RgbaImage reference;
        if (scored) reference = tonemapped(toRgba(frame.get(tracer::Channel::Reference)), o.exposure);
        if (scored && o.writeReferencePng) writePngOutput(o, out, "reference", frame.index, reference);
        for (size_t c = 0; c < result.chains.size(); ++c) {
            auto& chain = result.chains[c];
            const std::string what = chain.name + " on frame " + std::to_string(frame.index);
            if (scored)
                scoreOrWarn(result, what, [&] { chain.scored.push_back({frame.index, metrics.compare(display[c].rgba, reference.rgba)}); });
            if (f > 0 && !gap)
                scoreOrWarn(result, what + " (temporal error)", [&] {
                    chain.temporalError.push_back(metrics.temporalError(display[c].rgba, previous[c].rgba));
                });
        }
        if (scored) {
            const bool pair = f > 0 && !gap && !previousReference.rgba.empty();
            scoreTemporalArtifacts(result, display, previous, reference, pair ? &previousReference : nullptr,
                                   hasGeometry ? ages.recentMask() : std::vector<uint8_t>{}, metrics);
        }
        if (o.sideBySide) {   // frames without a reference get the strip without its last panel
            std::vector<const RgbaImage*> panels;
            for (const auto& d : display) panels.push_back(&d);
            if (scored) panels.push_back(&reference);
            const auto strip = cli::sideBySide(panels);
            writePngOutput(o, out, "side_by_side", frame.index, strip);
        }
        previous = std::move(display);
        previousReference = scored ? std::move(reference) : RgbaImage{};
        if (!o.quiet)
            progress.update(double(f + 1) / double(o.framePaths.size()),
                        "frame " + std::to_string(f + 1) + "/" + std::to_string(o.framePaths.size()));
    }
    for (size_t c = 0; c < runs.size(); ++c) {
        auto& r = result.chains[c + 1];
        r.passOrder = runs[c]->passNames();
        r.passMs = runs[c]->passMs();
        r.frameMs = runs[c]->frameMs();
        const auto memory = runs[c]->graph().memory();
        r.transientBytes = memory.transientAliasedBytes;
        r.transientUnaliasedBytes = memory.transientUnaliasedBytes;
        r.historyBytes = memory.historyBytes;
    }
    result.frames = uint32_t(o.framePaths.size());
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!o.quiet)
        progress.finish("done: " + std::to_string(result.frames) + " frames, " + std::to_string(runs.size()) +
                        " chain(s) in " + formatSeconds(result.seconds));
    return result;
}

} // namespace hush::cli
