#pragma once
// Measuring one configuration of a sweep over one frame source: the denoise job run
// once (and twice more for --lag), reduced to a SweepPoint. hush sweep and budget
// mode without a sweep (hush denoise --budget-ms) share it.
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include <hush/rhi/device.hpp>

#include "denoise_job.hpp"
#include "sweep_result.hpp"

namespace hush::cli {

class OutputFolder;

struct SourceFrames {
    SweepSource source;
    std::vector<std::string> paths;
    // The frames the quality means are taken over: every k-th of a rendered source
    // (not the extra references of --reference-pairs and --lag); empty: every frame
    // with a reference (a frames folder).
    std::set<uint32_t> scheduled;
    uint32_t stepFrame = ~0u;   // --lag: the frame the lighting step starts at
};

// The indices of the frames in `paths` that carry a reference.
std::vector<uint32_t> scoredFrames(const std::vector<std::string>& paths);

// Runs `chain` (a built-in name or chain file) over the source; `config` names the
// point; the noisy input's scores come with it. With `writeImages`, the scored
// frames' PNGs go to <out>/runs/<source>/.
SweepPoint measure(const rhi::Device& device, const SourceFrames& s, const std::string& chain,
                   const std::string& config, OutputFolder& out, SweepQuality& noisy, bool writeImages = true);

// Budget mode without a sweep: the built-in chains at their defaults over `framePaths`
// (which must carry references), measured in memory (nothing written).
SweepResult quickSweep(const rhi::Device& device, const std::vector<std::string>& framePaths, OutputFolder& out);

} // namespace hush::cli
