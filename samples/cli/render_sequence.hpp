#pragma once
// Rendering a sequence of frames to a folder with progress and an estimate of the
// time left: `hush render` and `hush demo` share it.
#include <string>

#include <hush/tracer/renderer.hpp>

namespace hush::cli {

struct SequenceRequest {
    tracer::RenderSettings settings;   // referenceSpp 0: no references
    uint32_t first = 0;
    uint32_t frames = 16;
    uint32_t referenceEvery = 1;       // a reference on frames first + k * every + offset
    uint32_t referenceOffset = 0;
    bool referencePairs = false;       // also a reference on the frame before each (flicker needs pairs)
    uint32_t referencesFrom = ~0u;     // and a reference on every frame from this index on (lag)
    std::string outFolder;             // must exist
};

// Returns the seconds taken.
double renderSequence(const tracer::Renderer& renderer, const SequenceRequest& request);

} // namespace hush::cli
