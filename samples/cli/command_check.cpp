// `hush check <folder>`: reads an integrator's frames and reports, convention by
// convention, whether they follow docs/frame-format.md, with the evidence
// (hush::tracer::checkFrameConventions does the measuring).
#include <algorithm>
#include <cstdio>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <hush/core/error.hpp>
#include <hush/tracer/frame_check.hpp>
#include <hush/tracer/frame_io.hpp>

#include "command.hpp"

namespace hush::cli {
namespace {

constexpr std::string_view kUsage =
    "usage: hush check <folder> [--first <i>] [--frames <n>]\n"
    "\n"
    "Checks a sequence of frames (frame_<N>.exr, docs/frame-format.md) for the input\n"
    "conventions integrations most often get wrong, silently, and prints each as pass,\n"
    "FAIL or skip with what was measured:\n"
    "  motion    previous minus current position, in pixels, y down (tries -motion,\n"
    "            y flipped, NDC and UV units: whichever matches the previous frame)\n"
    "  camera    positions project to their own pixels through hush.camera.*, and\n"
    "            the two cameras predict the motion of static geometry\n"
    "  normal    unit length, world space (not view space), following the positions\n"
    "  depth     linear distance along the view axis (not a z-buffer value)\n"
    "  meshid    whole ids, 0xFFFFFFFF exactly where nothing is hit\n"
    "  albedo    in [0, 1], noise-free (no lighting in it)\n"
    "  radiance  finite, non-negative, linear HDR (not clipped, not sRGB)\n"
    "A check needing a layer the frames lack is skipped, naming the layer.\n"
    "\n"
    "options:\n"
    "  --first <i>   start at the i-th frame file of the folder (default 0)\n"
    "  --frames <n>  check n consecutive frames (default 4; motion needs 2)\n"
    "\n"
    "exit status: 0 nothing failed, 1 a convention failed, 2 could not run\n";

struct CheckOptions {
    std::string folder;
    uint32_t first = 0;
    uint32_t frames = 4;
};

CheckOptions parseCheckOptions(std::span<const std::string_view> args) {
    CheckOptions options;
    for (size_t i = 0; i < args.size(); ++i) {
        std::string v;
        if (takeOption(args, i, "--first", v)) options.first = parseCount(v, "--first", 0);
        else if (takeOption(args, i, "--frames", v)) options.frames = parseCount(v, "--frames", 1, 1000);
        else if (!args[i].starts_with("-") && options.folder.empty()) options.folder = std::string(args[i]);
        else unknownArgument("check", args[i]);
    }
    if (options.folder.empty()) throw Error(ErrorKind::InvalidArgument, "hush check: name the folder of frames to check");
    return options;
}

int runCheck(std::span<const std::string_view> args) {
    const CheckOptions options = parseCheckOptions(args);
    const std::vector<std::string> files = tracer::listFrames(options.folder);
    if (options.first >= files.size())
        throw Error(ErrorKind::InvalidArgument, "hush check: --first " + std::to_string(options.first) + ": '" +
                                                    options.folder + "' holds " + std::to_string(files.size()) + " frames");
    const size_t end = std::min<size_t>(files.size(), size_t(options.first) + options.frames);
    std::vector<tracer::Frame> frames;
    for (size_t i = options.first; i < end; ++i) {
        tracer::ReadOptions read;
        if (!frames.empty()) read.expectedWidth = frames[0].width, read.expectedHeight = frames[0].height;
        frames.push_back(tracer::readFrame(files[i], read));
    }
    std::printf("hush check: %zu frame(s) of %s (%s .. %s), %ux%u\n", frames.size(), options.folder.c_str(),
                files[options.first].c_str(), files[end - 1].c_str(), frames[0].width, frames[0].height);
    int failures = 0, passes = 0;
    for (const tracer::ConventionCheck& check : tracer::checkFrameConventions(frames)) {
        std::printf("  %-4s  %-8s  %s\n", tracer::verdictName(check.verdict), check.convention.c_str(),
                    check.evidence.c_str());
        failures += check.verdict == tracer::CheckVerdict::Fail;
        passes += check.verdict == tracer::CheckVerdict::Pass;
    }
    std::printf("%d passed, %d failed, %d skipped\n", passes, failures, 7 - passes - failures);
    return failures ? kExitFailed : kExitOk;
}

} // namespace

const Command& checkCommand() {
    static const Command command{"check", "check an integrator's frames against hush's input conventions", kUsage,
                                 &runCheck};
    return command;
}

} // namespace hush::cli
