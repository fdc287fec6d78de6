#pragma once
// World: the scene at one instant, in world space, in an Embree BVH, with what
// next-event estimation needs (the emissive triangles with a power CDF, the sun).
#include <cstdint>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include <hush/tracer/renderer.hpp>
#include <hush/tracer/scene.hpp>

namespace hush::tracer::detail {

struct Hit {
    bool valid = false;
    float t = 0.0f;
    glm::vec3 position{0.0f};
    glm::vec3 geometricNormal{0.0f};   // unit, facing the incoming ray
    glm::vec3 shadingNormal{0.0f};     // unit, on the same side as geometricNormal
    bool frontFace = true;             // the ray arrived on the counter-clockwise side
    uint32_t mesh = ~0u;
    uint32_t triangle = 0;
    const Material* material = nullptr;
};

struct LightSample {
    glm::vec3 direction{0.0f};   // unit, from the shading point towards the light
    float distance = 0.0f;       // to the light point; infinity for the sun
    glm::vec3 radiance{0.0f};
    float pdf = 0.0f;            // solid angle, including the choice of light
};

class World {
public:
    World(RTCDevice device, const Scene& scene, float time);
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    Hit intersect(glm::vec3 origin, glm::vec3 direction, float tMax = 1e30f) const;
    bool occluded(glm::vec3 origin, glm::vec3 direction, float tMax) const;

    bool hasLights() const { return sunProbability_ > 0.0f || !emitters_.empty(); }
    LightSample sampleLight(glm::vec3 from, float choice, glm::vec2 u) const;
    // The pdf sampleLight would give for reaching this emitter hit from `from`.
    float emitterPdf(glm::vec3 from, const Hit& hit) const;
    // Radiance of a ray that leaves the scene, split into the sun (which light
    // sampling also reaches, so it is MIS-weighted) and the sky (which it does not).
    glm::vec3 skyRadiance(glm::vec3 direction) const;
    glm::vec3 sunRadiance(glm::vec3 direction) const;
    float sunPdf(glm::vec3 direction) const;

    // Queries this thread has made through any World so far (a thread-local count,
    // so that counting costs no shared cache line per ray).
    static RayCounts raysCastOnThisThread();
    // The BVH itself, for the ray-casting probe (ray_cast_probe.cpp).
    RTCScene embreeScene() const { return rtc_; }
    const glm::mat4& transform(uint32_t mesh) const { return transforms_[mesh]; }
    float sceneScale() const { return scale_; }

private:
    struct Emitter {
        glm::vec3 v0, e1, e2, normal;   // normal: the front face's (counter-clockwise)
        float area;
        glm::vec3 radiance;
        bool doubleSided;
    };
    // The cosine between an emitter's emitting side and the way to `towards`; 0 when
    // `towards` sees its back.
    static float emittingCosine(const Emitter& e, glm::vec3 fromLightTowards);

    const Scene& scene_;
    RTCScene rtc_ = nullptr;
    std::vector<glm::mat4> transforms_;
    std::vector<std::vector<glm::vec3>> worldNormals_;   // per mesh, per vertex (empty: face normals)
    std::vector<std::vector<glm::vec3>> worldPositions_; // per mesh, per vertex: for front faces
    std::vector<std::vector<uint32_t>> emitterIndex_;     // per mesh, per triangle: index into emitters_ or ~0u
    std::vector<Emitter> emitters_;
    std::vector<float> emitterCdf_;
    float sunProbability_ = 0.0f;
    glm::vec3 sunDirection_{0.0f};   // towards the sun
    float sunCosMax_ = 1.0f;
    float scale_ = 1.0f;
};

} // namespace hush::tracer::detail
