// The ray-casting probe: the tracer's rays, cast through Embree with nothing around
// them. Primary rays one at a time and in packets of 8 (the coherence a packet
// tracer would exploit), then incoherent rays from the primary hits, as closest-hit
// and as occlusion queries.
#include <hush/tracer/ray_cast_probe.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <utility>
#include <vector>

#include <embree3/rtcore.h>

#include <hush/core/error.hpp>

#include "camera_model.hpp"
#include "parallel_rows.hpp"
#include "path_integrator.hpp"
#include "sampling.hpp"
#include "world.hpp"

namespace hush::tracer {

using namespace detail;

double RayCastRates::secondsFor(uint64_t primaryRays, uint64_t bounceRays, uint64_t shadowRays) const {
    double seconds = 0.0;
    for (auto [rays, rate] : {std::pair{primaryRays, primary}, {bounceRays, bounce}, {shadowRays, shadow}}) {
        if (rays == 0) continue;
        if (!(rate > 0.0)) return 0.0;
        seconds += double(rays) / (rate * 1e6);
    }
    return seconds;
}

namespace {

struct Secondary {
    glm::vec3 origin, direction;
};

RTCRay rayOf(glm::vec3 origin, glm::vec3 direction) {
    RTCRay ray{};
    ray.org_x = origin.x, ray.org_y = origin.y, ray.org_z = origin.z;
    ray.dir_x = direction.x, ray.dir_y = direction.y, ray.dir_z = direction.z;
    ray.tnear = 0.0f;
    ray.tfar = 1e30f;
    ray.mask = ~0u;
    return ray;
}

// Runs rowRays (which returns the rays it cast in its row) over every row, `repeats`
// times, and gives the median rate in Mrays/s.
template <class RowFn>
double medianRate(uint32_t rows, const RayCastProbeSettings& s, RowFn rowRays) {
    std::vector<double> rates;
    for (uint32_t r = 0; r < s.repeats; ++r) {
        std::atomic<uint64_t> rays{0};
        const auto start = std::chrono::steady_clock::now();
        parallelRows(rows, s.threads, [&](uint32_t y) { rays += rowRays(y); });
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        rates.push_back(seconds > 0.0 ? double(rays.load()) / seconds * 1e-6 : 0.0);
    }
    std::sort(rates.begin(), rates.end());
    return rates[rates.size() / 2];
}

uint64_t primaryRow(RTCScene scene, const CameraModel& camera, uint32_t y) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (uint32_t x = 0; x < camera.width; ++x) {
        RTCRayHit rh{};
        rh.ray = rayOf(camera.position, camera.rayDirection({float(x) + 0.5f, float(y) + 0.5f}));
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &rh);
    }
    return camera.width;
}

// Rows 2y and 2y + 1, in packets of 4x2 pixels.
uint64_t primaryPacketRows(RTCScene scene, const CameraModel& camera, uint32_t pair) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    uint64_t rays = 0;
    for (uint32_t x0 = 0; x0 < camera.width; x0 += 4) {
        alignas(32) RTCRayHit8 rh{};
        alignas(32) int valid[8];
        for (int lane = 0; lane < 8; ++lane) {
            const uint32_t x = x0 + uint32_t(lane % 4), y = 2 * pair + uint32_t(lane / 4);
            valid[lane] = (x < camera.width && y < camera.height) ? -1 : 0;
            const glm::vec3 d = camera.rayDirection({float(x) + 0.5f, float(y) + 0.5f});
            rh.ray.org_x[lane] = camera.position.x, rh.ray.org_y[lane] = camera.position.y;
            rh.ray.org_z[lane] = camera.position.z;
            rh.ray.dir_x[lane] = d.x, rh.ray.dir_y[lane] = d.y, rh.ray.dir_z[lane] = d.z;
            rh.ray.tnear[lane] = 0.0f, rh.ray.tfar[lane] = 1e30f, rh.ray.mask[lane] = ~0u;
            rh.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
            rays += valid[lane] ? 1 : 0;
        }
        rtcIntersect8(valid, scene, &context, &rh);
    }
    return rays;
}

// From each primary hit, a cosine-distributed direction around its normal (a fixed
// hash of the pixel, so every pass casts the same rays).
std::vector<std::vector<Secondary>> secondaryRays(const World& world, const CameraModel& camera,
                                                  const RayCastProbeSettings& s) {
    std::vector<std::vector<Secondary>> rows(camera.height);
    parallelRows(camera.height, s.threads, [&](uint32_t y) {
        for (uint32_t x = 0; x < camera.width; ++x) {
            const Hit hit = world.intersect(camera.position, camera.rayDirection({float(x) + 0.5f, float(y) + 0.5f}));
            if (!hit.valid) continue;
            const uint32_t key = hashCombine(hashCombine(s.frameIndex, x), y);
            const glm::vec2 u(float(hash32(key) >> 8) * 0x1p-24f, float(hash32(key + 1) >> 8) * 0x1p-24f);
            const glm::vec3 d = Basis(hit.geometricNormal).toWorld(sampleCosineHemisphere(u));
            rows[y].push_back({offsetRay(hit, d), d});
        }
    });
    return rows;
}

void checkSettings(const RayCastProbeSettings& s) {
    if (s.width == 0 || s.height == 0 || s.width > 16384 || s.height > 16384)
        throw Error(ErrorKind::InvalidArgument, "ray-casting probe size " + std::to_string(s.width) + "x" +
                                                    std::to_string(s.height) + " must be between 1x1 and 16384x16384");
    if (s.repeats == 0) throw Error(ErrorKind::InvalidArgument, "ray-casting probe repeats must be at least 1");
}

} // namespace

RayCastRates probeRayCasting(const Scene& scene, const RayCastProbeSettings& s) {
    checkSettings(s);
    scene.validate();
    RTCDevice device = rtcNewDevice(nullptr);
    if (!device)
        throw Error(ErrorKind::Unsupported, "Embree could not create a device (error " +
                                                std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    struct DeviceGuard {
        RTCDevice d;
        ~DeviceGuard() { rtcReleaseDevice(d); }
    } guard{device};
    const float time = float(s.frameIndex) / scene.framesPerSecond;
    const World world(device, scene, time);
    const auto& path = scene.camera;
    const CameraModel camera = makeCamera(path.at(time), s.width, s.height, path.nearPlane, path.farPlane, {0.0f, 0.0f});
    const RTCScene bvh = world.embreeScene();
    const auto secondary = secondaryRays(world, camera, s);   // also warms the caches

    RayCastRates rates;
    rates.primary = medianRate(s.height, s, [&](uint32_t y) { return primaryRow(bvh, camera, y); });
    rates.primaryPacket = medianRate((s.height + 1) / 2, s, [&](uint32_t p) { return primaryPacketRows(bvh, camera, p); });
    rates.bounce = medianRate(s.height, s, [&](uint32_t y) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (const auto& r : secondary[y]) {
            RTCRayHit rh{};
            rh.ray = rayOf(r.origin, r.direction);
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(bvh, &context, &rh);
        }
        return uint64_t(secondary[y].size());
    });
    rates.shadow = medianRate(s.height, s, [&](uint32_t y) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (const auto& r : secondary[y]) {
            RTCRay ray = rayOf(r.origin, r.direction);
            rtcOccluded1(bvh, &context, &ray);
        }
        return uint64_t(secondary[y].size());
    });
    return rates;
}

} // namespace hush::tracer
