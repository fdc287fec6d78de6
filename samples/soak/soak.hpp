#pragma once
// A chain run for a long time, the way a long-lived application runs one: short
// sequences of the built-in scenes looped, and every `segmentFrames` frames a camera
// cut (the next scene) and a size change (a new runner, as an engine rebuilds its
// graph on resize). At each segment's end it samples what the process holds: its
// resident memory, the device memory hush allocated, and the RHI's live objects.
// A leak shows as growth between segments of the same size; the slopes are fitted
// over those. hush-bench-soak runs it for 10,000 frames, tests/passes/test_soak.cpp
// for 300.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <hush/rhi/rhi.hpp>

namespace hush::soak {

struct SoakPlan {
    std::string chain = "svgf";   // a built-in chain or a chain file
    uint32_t frames = 10000;
    uint32_t segmentFrames = 1000;
    std::vector<rhi::Extent2D> sizes = {{64, 64}, {48, 40}, {64, 32}};   // cycled, one per segment
    std::vector<std::string> scenes = {"glossy", "room", "thin"};       // cycled, one per segment
    uint32_t sequenceFrames = 8;   // each scene's rendered frames, looped within a segment
};

struct SoakSample {
    uint32_t frame = 0;   // frames run so far
    rhi::Extent2D size;
    std::string scene;
    uint64_t residentBytes = 0;   // the process's resident set (/proc/self/statm)
    uint64_t deviceBytes = 0;     // Device::allocatedBytes()
    int64_t liveObjects = 0;      // rhi::liveObjects().total()
    uint64_t nonFinite = 0;       // non-finite display values in the segment
    double msPerFrame = 0.0;      // wall clock, upload and read-back included
};

struct SoakResult {
    std::vector<SoakSample> samples;
    // Least-squares growth per 1,000 frames, fitted per size over that size's samples
    // and averaged; zero for a process that holds nothing more as it runs.
    double residentBytesPer1000 = 0.0;
    double deviceBytesPer1000 = 0.0;
    double liveObjectsPer1000 = 0.0;
};

// Runs `plan` on `device`; `onSample` (optional) sees each sample as it is taken.
// Throws hush::Error naming the chain or scene when either is unknown.
SoakResult runSoak(const rhi::Device& device, const SoakPlan& plan,
                   const std::function<void(const SoakSample&)>& onSample = {});

// The process's resident set in bytes (0 where /proc is missing).
uint64_t residentBytes();

} // namespace hush::soak
