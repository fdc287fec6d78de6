#include "world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include <hush/core/error.hpp>

#include "sampling.hpp"

namespace hush::tracer::detail {

World::World(RTCDevice device, const Scene& scene, float time) : scene_(scene), scale_(scene.sceneScale) {
    rtc_ = rtcNewScene(device);
    rtcSetSceneBuildQuality(rtc_, RTC_BUILD_QUALITY_MEDIUM);
    // Watertight: without it rays through an edge shared by two triangles can slip
    // between them, and a closed room leaks light (the white furnace test sees it).
    rtcSetSceneFlags(rtc_, RTC_SCENE_FLAG_ROBUST);
    transforms_.resize(scene.meshes.size());
    worldNormals_.resize(scene.meshes.size());
    worldPositions_.resize(scene.meshes.size());
    emitterIndex_.resize(scene.meshes.size());
    for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        const glm::mat4 toWorld = mesh.transformAt(time);
        transforms_[m] = toWorld;
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(toWorld)));

        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                     3 * sizeof(float), mesh.positions.size()));
        auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                       3 * sizeof(uint32_t), mesh.triangles.size()));
        if (!vertices || !indices)
            throw Error(ErrorKind::OutOfMemory, "Embree could not allocate mesh '" + mesh.name + "'");
        std::vector<glm::vec3> world(mesh.positions.size());
        for (size_t i = 0; i < mesh.positions.size(); ++i) {
            world[i] = glm::vec3(toWorld * glm::vec4(mesh.positions[i], 1.0f));
            vertices[3 * i + 0] = world[i].x;
            vertices[3 * i + 1] = world[i].y;
            vertices[3 * i + 2] = world[i].z;
        }
        for (size_t i = 0; i < mesh.triangles.size(); ++i) {
            indices[3 * i + 0] = mesh.triangles[i].x;
            indices[3 * i + 1] = mesh.triangles[i].y;
            indices[3 * i + 2] = mesh.triangles[i].z;
        }
        worldPositions_[m] = world;
        rtcCommitGeometry(geometry);
        rtcAttachGeometryByID(rtc_, geometry, m);   // geometry ID = mesh index
        rtcReleaseGeometry(geometry);

        if (!mesh.normals.empty()) {
            auto& normals = worldNormals_[m];
            normals.resize(mesh.normals.size());
            for (size_t i = 0; i < mesh.normals.size(); ++i) normals[i] = glm::normalize(normalMatrix * mesh.normals[i]);
        }
        const Material& material = scene.materials[mesh.material];
        if (glm::any(glm::greaterThan(material.emission, glm::vec3(0.0f)))) {
            auto& index = emitterIndex_[m];
            index.assign(mesh.triangles.size(), ~0u);
            for (size_t i = 0; i < mesh.triangles.size(); ++i) {
                const auto& t = mesh.triangles[i];
                Emitter e;
                e.v0 = world[t.x];
                e.e1 = world[t.y] - world[t.x];
                e.e2 = world[t.z] - world[t.x];
                const glm::vec3 n = glm::cross(e.e1, e.e2);
                e.area = 0.5f * glm::length(n);
                if (!(e.area > 0.0f)) continue;   // degenerate triangles emit nothing
                e.normal = n / (2.0f * e.area);
                e.radiance = material.emission;
                e.doubleSided = material.doubleSidedEmission;
                index[i] = uint32_t(emitters_.size());
                emitters_.push_back(e);
            }
        }
    }
    rtcCommitScene(rtc_);

    // Emitters are chosen in proportion to their power; with a sun, half the
    // samples go to it (any split is unbiased; half is robust for sun-lit interiors).
    float total = 0.0f;
    for (const auto& e : emitters_) {
        total += luminance(e.radiance) * e.area;
        emitterCdf_.push_back(total);
    }
    if (total > 0.0f)
        for (auto& c : emitterCdf_) c /= total;
    else
        emitters_.clear(), emitterCdf_.clear();
    const bool sun = luminance(scene.sun.radiance) > 0.0f;
    sunProbability_ = sun ? (emitters_.empty() ? 1.0f : 0.5f) : 0.0f;
    if (sun) {
        glm::vec3 travel = glm::normalize(scene.sun.direction);
        if (!scene.sun.motion.empty()) {
            Mesh carrier;   // reuse the keyframe interpolation of meshes
            carrier.motion = scene.sun.motion;
            travel = glm::normalize(glm::vec3(carrier.transformAt(time) * glm::vec4(travel, 0.0f)));
        }
        sunDirection_ = -travel;
        sunCosMax_ = std::cos(glm::radians(std::max(scene.sun.angularRadiusDegrees, 1e-3f)));
    }
}

namespace {
thread_local RayCounts tlsRaysCast;
} // namespace

RayCounts World::raysCastOnThisThread() { return tlsRaysCast; }

World::~World() {
    if (rtc_) rtcReleaseScene(rtc_);
}

Hit World::intersect(glm::vec3 origin, glm::vec3 direction, float tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = origin.x;
    rh.ray.org_y = origin.y;
    rh.ray.org_z = origin.z;
    rh.ray.dir_x = direction.x;
    rh.ray.dir_y = direction.y;
    rh.ray.dir_z = direction.z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = tMax;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(rtc_, &context, &rh);
    ++tlsRaysCast.closestHit;
    Hit hit;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
    hit.valid = true;
    hit.t = rh.ray.tfar;
    hit.mesh = rh.hit.geomID;
    hit.triangle = rh.hit.primID;
    hit.position = origin + direction * hit.t;
    const Mesh& mesh = scene_.meshes[hit.mesh];
    hit.material = &scene_.materials[mesh.material];
    // The counter-clockwise face normal from our own vertices (not Embree's Ng, whose
    // orientation convention is Embree's), then turned to face the ray: surfaces
    // reflect on both sides, only emission cares which side was hit.
    const auto& tri = mesh.triangles[hit.triangle];
    const auto& wp = worldPositions_[hit.mesh];
    glm::vec3 ng = glm::cross(wp[tri.y] - wp[tri.x], wp[tri.z] - wp[tri.x]);
    const float ngLength = glm::length(ng);
    ng = ngLength > 0.0f ? ng / ngLength : glm::normalize(glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
    hit.frontFace = glm::dot(ng, direction) < 0.0f;
    if (!hit.frontFace) ng = -ng;
    hit.geometricNormal = ng;
    hit.shadingNormal = ng;
    const auto& normals = worldNormals_[hit.mesh];
    if (!normals.empty()) {
        const auto& t = mesh.triangles[hit.triangle];
        const float u = rh.hit.u, v = rh.hit.v;
        glm::vec3 ns = (1.0f - u - v) * normals[t.x] + u * normals[t.y] + v * normals[t.z];
        const float len = glm::length(ns);
        if (len > 1e-8f) {
            ns /= len;
            if (glm::dot(ns, ng) < 0.0f) ns = -ns;
            hit.shadingNormal = ns;
        }
    }
    return hit;
}

bool World::occluded(glm::vec3 origin, glm::vec3 direction, float tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = origin.x;
    ray.org_y = origin.y;
    ray.org_z = origin.z;
    ray.dir_x = direction.x;
    ray.dir_y = direction.y;
    ray.dir_z = direction.z;
    ray.tnear = 0.0f;
    ray.tfar = tMax;
    ray.mask = ~0u;
    rtcOccluded1(rtc_, &context, &ray);
    ++tlsRaysCast.occlusion;
    return ray.tfar < 0.0f;
}

LightSample World::sampleLight(glm::vec3 from, float choice, glm::vec2 u) const {
    LightSample s;
    if (choice < sunProbability_) {
        const Basis basis(sunDirection_);
        s.direction = glm::normalize(basis.toWorld(sampleUniformCone(u, sunCosMax_)));
        s.distance = std::numeric_limits<float>::infinity();
        s.radiance = scene_.sun.radiance;
        s.pdf = sunProbability_ / (2.0f * kPi * (1.0f - sunCosMax_));
        return s;
    }
    if (emitters_.empty()) return s;
    const float c = (choice - sunProbability_) / (1.0f - sunProbability_);
    const size_t i = std::min(size_t(std::lower_bound(emitterCdf_.begin(), emitterCdf_.end(), c) - emitterCdf_.begin()),
                              emitters_.size() - 1);
    const Emitter& e = emitters_[i];
    const glm::vec2 b = sampleUniformTriangle(u);
    const glm::vec3 point = e.v0 + b.x * e.e1 + b.y * e.e2;
    const glm::vec3 toLight = point - from;
    const float d2 = glm::dot(toLight, toLight);
    if (!(d2 > 0.0f)) return s;
    s.distance = std::sqrt(d2);
    s.direction = toLight / s.distance;
    const float cosLight = emittingCosine(e, -s.direction);
    if (cosLight < 1e-6f) return s;
    const float choose = (1.0f - sunProbability_) * (emitterCdf_[i] - (i ? emitterCdf_[i - 1] : 0.0f));
    s.pdf = choose * d2 / (cosLight * e.area);
    s.radiance = e.radiance;
    return s;
}

float World::emitterPdf(glm::vec3 from, const Hit& hit) const {
    if (!hit.valid || emitters_.empty()) return 0.0f;
    const auto& index = emitterIndex_[hit.mesh];
    if (index.empty() || index[hit.triangle] == ~0u) return 0.0f;
    const uint32_t i = index[hit.triangle];
    const Emitter& e = emitters_[i];
    const glm::vec3 d = hit.position - from;
    const float d2 = glm::dot(d, d);
    const float cosLight = emittingCosine(e, -glm::normalize(d));
    if (cosLight < 1e-6f) return 0.0f;
    const float choose = (1.0f - sunProbability_) * (emitterCdf_[i] - (i ? emitterCdf_[i - 1] : 0.0f));
    return choose * d2 / (cosLight * e.area);
}

float World::emittingCosine(const Emitter& e, glm::vec3 fromLightTowards) {
    const float c = glm::dot(e.normal, fromLightTowards);
    return e.doubleSided ? std::abs(c) : std::max(c, 0.0f);
}

glm::vec3 World::skyRadiance(glm::vec3 direction) const {
    const Sky& sky = scene_.sky;
    if (direction.y < 0.0f) return sky.ground;
    return glm::mix(sky.horizon, sky.zenith, std::sqrt(std::clamp(direction.y, 0.0f, 1.0f)));
}

glm::vec3 World::sunRadiance(glm::vec3 direction) const {
    if (sunProbability_ <= 0.0f || glm::dot(direction, sunDirection_) < sunCosMax_) return glm::vec3(0.0f);
    return scene_.sun.radiance;
}

float World::sunPdf(glm::vec3 direction) const {
    if (sunProbability_ <= 0.0f || glm::dot(direction, sunDirection_) < sunCosMax_) return 0.0f;
    return sunProbability_ / (2.0f * kPi * (1.0f - sunCosMax_));
}

} // namespace hush::tracer::detail
