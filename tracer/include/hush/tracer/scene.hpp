#pragma once
// Scene: meshes with layered Lambert + GGX materials (Mara et al., seed 000 Eq. 1-4),
// emissive surfaces (area lights), a sun and a sky, and a named, animated camera
// path. Plain data: built-in scenes, OBJ+MTL and JSON scene files all produce it.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace hush::tracer {

// f = m (1 - F)^2 + g F (seed 000 Eq. 1), m = albedo / pi (Lambert), g = GGX with
// alpha = roughness, F = Schlick with F0 = specular (Eq. 4).
struct Material {
    std::string name;
    glm::vec3 albedo{0.8f};       // diffuse reflectance rho_L
    glm::vec3 specular{0.0f};     // F0; 0 means a purely matte surface
    float roughness = 0.5f;       // GGX alpha; below kMirrorRoughness the lobe is a mirror
    glm::vec3 emission{0.0f};     // emitted radiance (an area light when non-zero)
    // Area lights emit from their front face, the side their triangles wind
    // counter-clockwise on (as in the reference renderer of the Cornell box); set
    // this for a light that emits from both sides.
    bool doubleSidedEmission = false;
};

inline constexpr float kMirrorRoughness = 1e-3f;

// A rigid motion over time: keyframes of translation (and a rotation about +Y),
// linearly interpolated and held past the ends. Empty: the mesh does not move.
struct Keyframe {
    float time = 0.0f;            // seconds
    glm::vec3 translation{0.0f};
    float rotationYDegrees = 0.0f;
};

struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;   // object space
    std::vector<glm::vec3> normals;     // per vertex (shading); empty: use face normals
    std::vector<glm::uvec3> triangles;  // indices into positions (and normals)
    uint32_t material = 0;              // index into Scene::materials
    std::vector<Keyframe> motion;       // object -> world at time t
    glm::mat4 transformAt(float time) const;
};

struct Sun {
    glm::vec3 direction{0.0f, -1.0f, 0.0f};   // the way the light travels (towards the scene)
    glm::vec3 radiance{0.0f};                 // 0: no sun
    float angularRadiusDegrees = 0.27f;
    std::vector<Keyframe> motion;             // rotationYDegrees turns the direction about +Y
};

// A sky dome: radiance blends from horizon to zenith by the elevation of the direction.
struct Sky {
    glm::vec3 zenith{0.0f};
    glm::vec3 horizon{0.0f};
    glm::vec3 ground{0.0f};   // below the horizon
};

struct CameraKey {
    float time = 0.0f;
    glm::vec3 position{0.0f, 0.0f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float verticalFovDegrees = 45.0f;
};

struct CameraPath {
    std::string name;             // e.g. "orbit", "dolly"
    std::vector<CameraKey> keys;  // sorted by time; linear interpolation, held past the ends
    float nearPlane = 0.1f;
    float farPlane = 1000.0f;
    CameraKey at(float time) const;
};

struct Scene {
    std::string name;
    std::vector<Material> materials;
    std::vector<Mesh> meshes;
    Sun sun;
    Sky sky;
    CameraPath camera;
    float framesPerSecond = 30.0f;   // frame i is at time i / framesPerSecond
    float sceneScale = 1.0f;         // metres per scene unit (Mara's d0/d1 are in metres)

    // Throws hush::Error naming the mesh or material: out-of-range indices, a mesh
    // without triangles, non-finite numbers, negative radiance.
    void validate() const;
};

} // namespace hush::tracer
