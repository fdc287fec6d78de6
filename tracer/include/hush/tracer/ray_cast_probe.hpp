#pragma once
// The path tracer's roofline: how fast Embree alone casts rays through a scene's BVH
// on this machine, with no shading, sampling or frame writes around it. Issue 14
// measures hush-bench-tracer's Mrays/s against it (docs/benchmarks.md, "Path tracer").
#include <cstdint>

#include <hush/tracer/scene.hpp>

namespace hush::tracer {

struct RayCastProbeSettings {
    uint32_t frameIndex = 0;   // the camera and the meshes at this frame's time
    uint32_t width = 640;
    uint32_t height = 360;
    uint32_t repeats = 3;      // timed passes over the image per ray kind (the median is kept)
    uint32_t threads = 0;      // 0: every core
};

// Millions of rays per second, each kind the median of `repeats` passes.
struct RayCastRates {
    double primary = 0.0;        // a camera ray per pixel centre, one at a time (rtcIntersect1), as the tracer casts them
    double primaryPacket = 0.0;  // the same rays in packets of 8 (4x2 pixels, rtcIntersect8)
    double bounce = 0.0;         // from each primary hit, a cosine-distributed ray (rtcIntersect1): incoherent
    double shadow = 0.0;         // the same directions as occlusion rays of unbounded length (rtcOccluded1)
    // The seconds Embree alone would take for a frame's rays at these rates (0 when a
    // kind that is asked for was not measured): the roofline of a tracer that cast
    // them, Renderer::raysCast split into its primary rays and the rest.
    double secondsFor(uint64_t primaryRays, uint64_t bounceRays, uint64_t shadowRays) const;
};

// Builds the scene's BVH at the frame's time (not timed) and times each ray kind.
RayCastRates probeRayCasting(const Scene& scene, const RayCastProbeSettings& settings);

} // namespace hush::tracer
