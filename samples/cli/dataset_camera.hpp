#pragma once
// Training sequences need camera motion the scenes' own paths do not have (Chaitanya
// et al. 2017 Sec. 4.3: fly-throughs, random subsequences, camera stops). A sequence's
// camera starts somewhere along the scene's path, displaced, and moves along the path
// at a random speed and direction, or stands still.
#include <cstdint>

#include <hush/tracer/scene.hpp>

namespace hush::cli {

struct SequenceCamera {
    tracer::CameraPath path;
    uint32_t firstFrame = 0;   // the scene's animation time of the sequence's frame 0
};

// Deterministic in (scene path, seed). `frames` at `framesPerSecond`.
SequenceCamera randomSequenceCamera(const tracer::CameraPath& base, uint64_t seed, uint32_t frames,
                                    float framesPerSecond);

} // namespace hush::cli
