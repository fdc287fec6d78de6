// Renderer: one World per frame time, rows shared out to threads (parallelRows),
// every pixel's estimates written into the frame's channels.
#include <hush/tracer/renderer.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <mutex>

#include <embree3/rtcore.h>

#include <hush/core/error.hpp>

#include "camera_model.hpp"
#include "parallel_rows.hpp"
#include "path_integrator.hpp"
#include "world.hpp"

namespace hush::tracer {

using namespace detail;

struct Renderer::Impl {
    Scene scene;
    RTCDevice device = nullptr;
    mutable std::atomic<uint64_t> closestHit{0}, occlusion{0};
    ~Impl() {
        if (device) rtcReleaseDevice(device);
    }
};

Renderer::Renderer(Scene scene) : impl_(std::make_unique<Impl>()) {
    scene.validate();
    impl_->scene = std::move(scene);
    impl_->device = rtcNewDevice(nullptr);
    if (!impl_->device)
        throw Error(ErrorKind::Unsupported, "Embree could not create a device (error " +
                                                std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
}

Renderer::~Renderer() = default;

const Scene& Renderer::scene() const { return impl_->scene; }
float Renderer::frameTime(uint32_t frameIndex) const { return float(frameIndex) / impl_->scene.framesPerSecond; }
RayCounts Renderer::raysCast() const { return {impl_->closestHit.load(), impl_->occlusion.load()}; }

namespace {

void checkSettings(const RenderSettings& s) {
    if (s.width == 0 || s.height == 0 || s.width > 16384 || s.height > 16384)
        throw Error(ErrorKind::InvalidArgument, "render size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                                    " must be between 1x1 and 16384x16384");
    if (s.channels.empty()) throw Error(ErrorKind::InvalidArgument, "no channels to render");
    if (s.bounces > 64) throw Error(ErrorKind::InvalidArgument, "bounces must be at most 64");
}

glm::vec3 finiteOrZero(glm::vec3 v) {
    return (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) ? v : glm::vec3(0.0f);
}

// The frame's images by channel, looked up once per frame rather than once per
// pixel and channel (with those map lookups the per-pixel loop took 8.5 % of a
// 1-spp frame's time; docs/benchmarks.md, "Less work around Embree").
class ChannelTable {
public:
    explicit ChannelTable(Frame& frame) {
        for (auto& [channel, image] : frame.channels) images_[size_t(channel)] = &image;
    }
    bool has(Channel c) const { return images_[size_t(c)] != nullptr; }
    void put(Channel c, uint32_t x, uint32_t y, glm::vec3 v) const {
        Image* image = images_[size_t(c)];
        if (!image) return;
        float* p = image->at(x, y);
        for (uint32_t i = 0; i < image->channels; ++i) p[i] = v[int(i)];
    }

    void clearRow(uint32_t y) const {
        for (Image* image : images_)
            if (image) std::fill_n(image->at(0, y), size_t(image->width) * image->channels, 0.0f);
    }

private:
    std::array<Image*, std::size(kAllChannels)> images_{};
};

// Gives `frame` exactly the channels asked for at the settings' size, keeping the
// images that already fit: rendering a sequence into one Frame then allocates its
// images once. (Fresh ones each frame cost 12 % of a 1-spp frame's CPU time at
// 1280x720, zeroing and page-faulting them on one thread; docs/benchmarks.md.)
void prepareFrame(Frame& frame, const RenderSettings& settings) {
    frame.width = settings.width;
    frame.height = settings.height;
    frame.referenceSpp = 0;
    const auto asked = [&](Channel c) {
        return std::find(settings.channels.begin(), settings.channels.end(), c) != settings.channels.end();
    };
    std::erase_if(frame.channels, [&](const auto& entry) {
        const Image& image = entry.second;
        return !asked(entry.first) || image.width != settings.width || image.height != settings.height ||
               image.channels != channelInfo(entry.first).components;
    });
    for (Channel c : settings.channels)
        if (!frame.has(c)) frame.add(c);
}

} // namespace

Frame Renderer::render(uint32_t frameIndex, const RenderSettings& settings, const ProgressFn& progress) const {
    Frame frame;
    renderInto(frame, frameIndex, settings, progress);
    return frame;
}

void Renderer::renderInto(Frame& frame, uint32_t frameIndex, const RenderSettings& settings,
                          const ProgressFn& progress) const {
    checkSettings(settings);
    const Scene& scene = impl_->scene;
    const float time = frameTime(frameIndex), previousTime = frameTime(frameIndex ? frameIndex - 1 : 0);
    const World world(impl_->device, scene, time);
    const glm::vec2 jitter = settings.jitter ? frameJitter(frameIndex) : glm::vec2(0.0f);
    const glm::vec2 previousJitter = settings.jitter ? frameJitter(frameIndex ? frameIndex - 1 : 0) : glm::vec2(0.0f);
    const auto& path = scene.camera;
    const CameraModel camera = makeCamera(path.at(time), settings.width, settings.height, path.nearPlane, path.farPlane, jitter);
    const CameraModel previous =
        makeCamera(path.at(previousTime), settings.width, settings.height, path.nearPlane, path.farPlane, previousJitter);

    prepareFrame(frame, settings);
    frame.index = frameIndex;
    frame.scene = scene.name;
    frame.metresPerUnit = scene.sceneScale;
    frame.camera = camera.info;
    frame.previousCamera = previous.info;
    const ChannelTable table(frame);
    const auto wants = [&](Channel c) { return table.has(c); };
    const auto put = [&](Channel c, uint32_t x, uint32_t y, glm::vec3 v) { table.put(c, x, y, v); };
    const bool mara = wants(Channel::Matte) || wants(Channel::Glossy);
    const bool path1 = wants(Channel::Color) || wants(Channel::Indirect) || (wants(Channel::Direct) && !mara);
    const bool reference = wants(Channel::Reference);
    if (reference) frame.referenceSpp = std::max(1u, settings.referenceSpp);
    const PathOptions options{settings.bounces, settings.regularization, settings.maraDirectSamples};

    // Each mesh's motion, from where a point is now to where it was last frame.
    std::vector<glm::mat4> nowToBefore(scene.meshes.size());
    for (size_t m = 0; m < scene.meshes.size(); ++m)
        nowToBefore[m] = scene.meshes[m].transformAt(previousTime) * glm::inverse(world.transform(uint32_t(m)));

    const uint64_t unitsPerRow = uint64_t(settings.width) * (1 + (reference ? frame.referenceSpp : 0));
    const uint64_t totalUnits = unitsPerRow * settings.height;
    std::atomic<uint64_t> doneUnits{0};
    std::mutex progressMutex;

    auto renderRow = [&](uint32_t y) {
        const RayCounts castBefore = World::raysCastOnThisThread();
        table.clearRow(y);   // a reused image holds the last frame's values
        for (uint32_t x = 0; x < settings.width; ++x) {
            const glm::vec2 pixel(float(x) + 0.5f + jitter.x, float(y) + 0.5f + jitter.y);
            const glm::vec3 dir = camera.rayDirection(pixel);
            const Hit hit = world.intersect(camera.position, dir);
            if (hit.valid) {
                const Material& m = *hit.material;
                put(Channel::Albedo, x, y, m.albedo);
                put(Channel::Specular, x, y, m.specular);
                put(Channel::Normal, x, y, hit.shadingNormal);
                put(Channel::Position, x, y, hit.position);
                put(Channel::Depth, x, y, glm::vec3(camera.viewDepth(hit.position)));
                put(Channel::Roughness, x, y, glm::vec3(m.roughness));
                put(Channel::MeshId, x, y, glm::vec3(float(hit.mesh)));
                // Seen directly, emission is noise-free: filters add it back after filtering.
                const bool facing = hit.frontFace || m.doubleSidedEmission;
                put(Channel::Emission, x, y, facing ? m.emission : glm::vec3(0.0f));
            } else {
                put(Channel::Depth, x, y, glm::vec3(path.farPlane));
                put(Channel::Position, x, y, camera.position + dir * path.farPlane);
                put(Channel::MeshId, x, y, glm::vec3(kNoMesh));
            }
            if (wants(Channel::Motion)) {
                // Where this surface point (or, for the sky, this direction) was last frame.
                glm::vec2 now, before;
                glm::vec3 point = hit.valid ? hit.position : camera.position + dir * path.farPlane;
                glm::vec3 pointBefore = point;
                if (hit.valid)
                    pointBefore = glm::vec3(nowToBefore[hit.mesh] * glm::vec4(point, 1.0f));
                else
                    pointBefore = previous.position + dir * path.farPlane;
                glm::vec3 motion(0.0f);
                if (camera.project(point, now) && previous.project(pointBefore, before)) motion = glm::vec3(before - now, 0.0f);
                put(Channel::Motion, x, y, motion);
            }
            if (wants(Channel::VirtualPos)) {
                // The reflected image of the scene lies beyond the surface by the mirror ray's length.
                glm::vec3 virtualPos = camera.position + dir * path.farPlane;
                if (hit.valid) {
                    const glm::vec3 r = glm::reflect(dir, hit.shadingNormal);
                    const Hit mirror = world.intersect(offsetRay(hit, r), r);
                    virtualPos = hit.position + dir * (mirror.valid ? mirror.t : path.farPlane);
                }
                put(Channel::VirtualPos, x, y, virtualPos);
            }
            if (path1) {
                PixelSampler sampler(settings.seed, x, y, frameIndex);
                const PathEstimate e = estimatePath(world, dir, hit, sampler, options);
                const glm::vec3 direct = finiteOrZero(e.direct), indirect = finiteOrZero(e.indirect);
                put(Channel::Color, x, y, direct + indirect);
                // Mara mode's direct term is light sampling only: what it cannot see
                // moves to `indirect`, so direct + indirect still estimates colour.
                put(Channel::Indirect, x, y, mara ? indirect + finiteOrZero(e.directUnsampled) : indirect);
                if (!mara) put(Channel::Direct, x, y, direct);
            }
            if (mara) {
                PixelSampler sampler(settings.seed ^ 0x6d617261u, x, y, frameIndex);
                const MaraEstimate e = estimateMara(world, dir, hit, sampler, options);
                put(Channel::Direct, x, y, finiteOrZero(e.direct));
                put(Channel::Matte, x, y, finiteOrZero(e.matte));
                put(Channel::Glossy, x, y, finiteOrZero(e.glossy));
            }
            if (reference) {
                // Independent of the noisy frames' samples (another key), same estimator.
                glm::dvec3 sum(0.0);
                for (uint32_t s = 0; s < frame.referenceSpp; ++s) {
                    PixelSampler sampler(settings.seed ^ 0x72656665u, x, y, uint64_t(frameIndex) * frame.referenceSpp + s);
                    glm::vec3 sampleDir = dir;
                    Hit sampleHit = hit;
                    if (settings.antialiasedReference) {
                        sampleDir = camera.rayDirection(glm::vec2(float(x), float(y)) + sampler.next2());
                        sampleHit = world.intersect(camera.position, sampleDir);
                    }
                    const PathEstimate e = estimatePath(world, sampleDir, sampleHit, sampler, options);
                    sum += glm::dvec3(finiteOrZero(e.direct + e.indirect));
                }
                put(Channel::Reference, x, y, glm::vec3(sum / double(frame.referenceSpp)));
            }
        }
        const RayCounts castAfter = World::raysCastOnThisThread();
        impl_->closestHit += castAfter.closestHit - castBefore.closestHit;
        impl_->occlusion += castAfter.occlusion - castBefore.occlusion;
        const uint64_t done = doneUnits += unitsPerRow;
        if (progress) {
            std::lock_guard lock(progressMutex);
            progress(done, totalUnits);
        }
    };

    parallelRows(settings.height, settings.threads, renderRow);
}

} // namespace hush::tracer
