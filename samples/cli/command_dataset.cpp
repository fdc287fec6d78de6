// `hush dataset`: training sequences for the recurrent denoising autoencoder
// (Chaitanya et al. 2017 Sec. 4.3; samples/rdae_training reads them). Each sequence is
// `frames` frames of one scene under a random camera (dataset_camera.hpp), with
// `noise` independent 1-spp colour estimates per frame sharing one G-buffer and one
// reference, all put through the network's own input node (RdaeInputChain), so that
// training sees exactly what inference sees. One .npy per sequence,
//   <out>/<scene>_<index>.npy: float16 [noise + 1, frames, 7, H, W]
// the last of the first axis being the reference through the same node. Sequences
// already on disk are skipped (a killed run resumes); --shard i/n takes every n-th.
#include <cstdio>
#include <filesystem>
#include <thread>

#include <hush/core/error.hpp>
#include <hush/passes/chain_runner.hpp>
#include <hush/passes/rdae/input.hpp>
#include <hush/passes/rdae/input_chain.hpp>
#include <hush/tracer/builtin_scenes.hpp>
#include <hush/tracer/renderer.hpp>

#include "command.hpp"
#include "dataset_camera.hpp"
#include "frame_upload.hpp"
#include "npy_file.hpp"
#include "progress.hpp"
#include "scene_argument.hpp"

namespace hush::cli {
namespace {

const std::string& usage() {
    static const std::string text =
        "usage: hush dataset --out <folder> [--sequences <n>] [--scenes <list>] [--frames <n>]\n"
        "                    [--size <W>x<H>] [--noise <n>] [--reference-spp <n>] [--seed <n>]\n"
        "                    [--shard <i>/<n>] [--adapter <text>]\n"
        "\n"
        "Renders training sequences for the recurrent denoising autoencoder (rdae) and\n"
        "writes each as <folder>/<scene>_<index>.npy, float16 of shape\n"
        "[noise + 1, frames, 7, H, W]: the network's input tensor for each 1-spp noise\n"
        "instance (demodulated colour^0.2, view-space normal xy, depth, roughness; made by\n"
        "the network's own input node) and, last, the same for the reference. Cameras are\n"
        "random variations of each scene's path. Existing files are kept, so a stopped\n"
        "run resumes; shards split the work between machines (samples/rdae_training).\n"
        "\n"
        "options:\n"
        "  --out <folder>         where the sequences go (created if missing)\n"
        "  --sequences <n>        sequences in all shards together (default 64)\n"
        "  --scenes <list>        built-in scenes or scene files, taken in turn (default\n"
        "                         room,glossy,moving-light,thin: cornell is held out)\n"
        "  --frames <n>           frames per sequence (default 7, the paper's)\n"
        "  --size <W>x<H>         frame size (default 128x128, the paper's crop)\n"
        "  --noise <n>            1-spp noise instances per frame (default 4)\n"
        "  --reference-spp <n>    samples per pixel of the references (default 256)\n"
        "  --seed <n>             cameras and samples (default 1)\n"
        "  --shard <i>/<n>        only sequences whose index is i modulo n (default 0/1)\n"
        "  --adapter <text>       use the first adapter whose name contains <text>\n";
    return text;
}

struct DatasetOptions {
    std::string outFolder;
    uint32_t sequences = 64, frames = 7, noise = 4, referenceSpp = 256, seed = 1, shard = 0, shards = 1;
    std::vector<std::string> scenes{"room", "glossy", "moving-light", "thin"};
    rhi::Extent2D size{128, 128};
};

void parseShard(const std::string& text, DatasetOptions& o) {
    const auto slash = text.find('/');
    if (slash == std::string::npos) throw Error(ErrorKind::InvalidArgument, "--shard takes <i>/<n>, got '" + text + "'");
    o.shards = parseCount(text.substr(slash + 1), "--shard's n", 1, 1u << 20);
    o.shard = parseCount(text.substr(0, slash), "--shard's i", 0, o.shards - 1);
}

// One frame's tensor (7 channels, cropped to the frame) into `out`.
void readTensor(const passes::ChainRunner& runner, rhi::Extent2D size, float* out) {
    const auto& chain = dynamic_cast<const passes::RdaeInputChain&>(runner.chain());
    const auto rgba = runner.readTexture(chain.tensor().texture);
    const auto layout = chain.tensor().layout();
    const auto padded = passes::rdaeLevelSize(size, 0, chain.tensorFormat().levels);
    const size_t textureWidth = size_t(padded.width) * layout.tilesX;
    for (uint32_t c = 0; c < passes::kRdaeInputChannels; ++c) {
        const uint32_t block = c / 4, tx = block % layout.tilesX, ty = block / layout.tilesX;
        for (uint32_t y = 0; y < size.height; ++y)
            for (uint32_t x = 0; x < size.width; ++x) {
                const size_t texel = (size_t(ty) * padded.height + y) * textureWidth + size_t(tx) * padded.width + x;
                out[(size_t(c) * size.height + y) * size.width + x] = rgba[texel * 4 + c % 4];
            }
    }
}

void renderSequence(passes::ChainRunner& runner, const DatasetOptions& o, uint32_t index,
                    const std::filesystem::path& file) {
    tracer::Scene scene = loadSceneArgument(o.scenes[index % o.scenes.size()]);
    const uint64_t sequenceSeed = uint64_t(o.seed) * 0x9E3779B97F4A7C15ull + index;
    const auto camera = randomSequenceCamera(scene.camera, sequenceSeed, o.frames, scene.framesPerSecond);
    scene.camera = camera.path;
    const tracer::Renderer renderer(scene);
    tracer::RenderSettings gbuffer;
    gbuffer.width = o.size.width;
    gbuffer.height = o.size.height;
    gbuffer.referenceSpp = o.referenceSpp;
    gbuffer.seed = uint32_t(sequenceSeed * 7919u);
    using C = tracer::Channel;
    gbuffer.channels = {C::Color, C::Emission, C::Albedo, C::Normal, C::Depth, C::Roughness, C::Reference};
    const size_t perFrame = size_t(passes::kRdaeInputChannels) * o.size.width * o.size.height;
    std::vector<float> values(size_t(o.noise + 1) * o.frames * perFrame);
    for (uint32_t f = 0; f < o.frames; ++f) {
        const tracer::Frame frame = renderer.render(camera.firstFrame + f, gbuffer);
        for (uint32_t k = 0; k <= o.noise; ++k) {
            std::vector<float> colour;
            if (k == o.noise) colour = frame.get(C::Reference).pixels;
            else if (k == 0) colour = frame.get(C::Color).pixels;
            else {
                tracer::RenderSettings another = gbuffer;
                another.channels = {C::Color};
                another.seed = gbuffer.seed + 104729u * k;
                colour = renderer.render(camera.firstFrame + f, another).get(C::Color).pixels;
            }
            frames::uploadFrame(runner, frame, [&](passes::InputChannel c, std::vector<float>& pixels, uint32_t) {
                if (c == passes::InputChannel::Color) pixels = colour;
            });
            runner.run();
            readTensor(runner, o.size, values.data() + (size_t(k) * o.frames + f) * perFrame);
        }
    }
    writeNpyHalf(file, {uint64_t(o.noise) + 1, o.frames, passes::kRdaeInputChannels, o.size.height, o.size.width}, values);
}

int runDataset(std::span<const std::string_view> args) {
    DatasetOptions o;
    rhi::AdapterRequest request;
    for (size_t i = 0; i < args.size(); ++i) {
        std::string v;
        if (takeOption(args, i, "--out", v)) o.outFolder = v;
        else if (takeOption(args, i, "--sequences", v)) o.sequences = parseCount(v, "--sequences", 1, 1u << 20);
        else if (takeOption(args, i, "--scenes", v)) o.scenes = splitList(v);
        else if (takeOption(args, i, "--frames", v)) o.frames = parseCount(v, "--frames", 1, 64);
        else if (takeOption(args, i, "--size", v)) {
            const auto size = parseSize(v, "--size");
            o.size = {size.width, size.height};
        }
        else if (takeOption(args, i, "--noise", v)) o.noise = parseCount(v, "--noise", 1, 64);
        else if (takeOption(args, i, "--reference-spp", v)) o.referenceSpp = parseCount(v, "--reference-spp", 1, 1u << 20);
        else if (takeOption(args, i, "--seed", v)) o.seed = parseCount(v, "--seed", 0, ~0u);
        else if (takeOption(args, i, "--shard", v)) parseShard(v, o);
        else if (takeOption(args, i, "--adapter", v)) request.nameContains = v, request.nameFromEnvironment = false;
        else unknownArgument("dataset", args[i]);
    }
    if (o.outFolder.empty()) throw Error(ErrorKind::InvalidArgument, "hush dataset needs --out <folder>");
    if (o.scenes.empty()) throw Error(ErrorKind::InvalidArgument, "--scenes names no scene");
    for (const auto& s : o.scenes) loadSceneArgument(s);   // fail now on a bad name, not after an hour
    std::filesystem::create_directories(o.outFolder);

    auto instance = rhi::Instance::create({});
    auto device = instance.requestAdapter(request).createDevice({.label = "hush dataset"});
    passes::ChainRunner runner(device, std::make_unique<passes::RdaeInputChain>(), o.size);
    std::vector<uint32_t> mine;
    for (uint32_t j = o.shard; j < o.sequences; j += o.shards) mine.push_back(j);
    std::printf("hush dataset: %zu of %u sequences (shard %u/%u) of %u frames at %ux%u, %u noise instances, "
                "reference %u spp -> %s\n",
                mine.size(), o.sequences, o.shard, o.shards, o.frames, o.size.width, o.size.height, o.noise,
                o.referenceSpp, o.outFolder.c_str());
    std::fflush(stdout);
    ProgressLine progress("dataset");
    uint32_t made = 0, kept = 0;
    for (size_t n = 0; n < mine.size(); ++n) {
        const uint32_t j = mine[n];
        char name[64];
        std::snprintf(name, sizeof name, "_%05u.npy", j);
        const auto file = std::filesystem::path(o.outFolder) / (o.scenes[j % o.scenes.size()] + name);
        if (std::filesystem::exists(file)) ++kept;
        else {
            renderSequence(runner, o, j, file);
            ++made;
        }
        progress.update(double(n + 1) / double(mine.size()), "sequence " + std::to_string(n + 1) + "/" +
                                                                  std::to_string(mine.size()));
    }
    progress.finish(std::to_string(made) + " written, " + std::to_string(kept) + " already there");
    return kExitOk;
}

} // namespace

const Command& datasetCommand() {
    static const Command command{"dataset", "render training sequences for the rdae network (.npy)", usage(), runDataset};
    return command;
}

} // namespace hush::cli
