#pragma once
// Renderer: renders frames of a scene's camera path with the Embree path tracer.
// Deterministic for a given seed (whatever the thread count); renders only the
// channels asked for.
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <hush/tracer/frame.hpp>
#include <hush/tracer/scene.hpp>

namespace hush::tracer {

struct RenderSettings {
    uint32_t width = 256;
    uint32_t height = 256;
    std::vector<Channel> channels = {Channel::Color,    Channel::Albedo, Channel::Normal, Channel::Position,
                                     Channel::Depth,    Channel::Motion, Channel::MeshId};
    uint32_t bounces = 1;             // indirect bounces after the primary hit (1: SVGF / BMFR's setting)
    uint32_t referenceSpp = 1024;     // samples of Channel::Reference
    uint32_t maraDirectSamples = 16;  // light samples of Mara's direct term (when matte or glossy is asked for)
    uint32_t seed = 1;
    bool jitter = false;              // per-frame subpixel offset of the primary rays (recorded in the frame)
    // The reference's pixel filter. Off: each reference sample follows the noisy
    // frame's own primary ray (pixel centre + jitter), so the reference is the
    // noise-free estimate for that hit, aliased as the input is. On: each sample goes
    // through a uniformly random point of the pixel (a box filter), the anti-aliased
    // image that temporal filters converge to (docs/tracer.md).
    bool antialiasedReference = false;
    float regularization = 0.0f;      // path-space regularisation: minimum GGX alpha after the primary hit
    uint32_t threads = 0;             // 0: every core
};

struct RayCounts {
    uint64_t closestHit = 0;   // rtcIntersect1: primary and bounce rays
    uint64_t occlusion = 0;    // rtcOccluded1: shadow rays
    uint64_t total() const { return closestHit + occlusion; }
};

// Called from the rendering threads, serialised: work units done out of total.
using ProgressFn = std::function<void(uint64_t done, uint64_t total)>;

class Renderer {
public:
    explicit Renderer(Scene scene);   // validates the scene
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    Frame render(uint32_t frameIndex, const RenderSettings& settings, const ProgressFn& progress = {}) const;
    // The same into `frame`, reusing its images where their size and channel fit (the
    // others are replaced, channels not asked for removed): a sequence rendered into
    // one Frame allocates its images once.
    void renderInto(Frame& frame, uint32_t frameIndex, const RenderSettings& settings,
                    const ProgressFn& progress = {}) const;
    const Scene& scene() const;
    float frameTime(uint32_t frameIndex) const;

    // Rays cast through Embree so far by this renderer, counted as they are cast:
    // closest-hit queries (primary and bounce rays) and occlusion (shadow) queries.
    RayCounts raysCast() const;
    uint64_t raysTraced() const { return raysCast().total(); }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace hush::tracer
