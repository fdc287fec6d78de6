#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include <hush/core/error.hpp>
#include <hush/tracer/scene.hpp>

namespace hush::tracer {

namespace {

template <class T, class Lerp>
T interpolate(const std::vector<T>& keys, float time, Lerp lerp) {
    if (time <= keys.front().time) return keys.front();
    if (time >= keys.back().time) return keys.back();
    const auto next = std::upper_bound(keys.begin(), keys.end(), time,
                                       [](float t, const T& k) { return t < k.time; });
    const auto& b = *next;
    const auto& a = *(next - 1);
    const float span = b.time - a.time;
    return lerp(a, b, span > 0.0f ? (time - a.time) / span : 0.0f);
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

} // namespace

glm::mat4 Mesh::transformAt(float time) const {
    if (motion.empty()) return glm::mat4(1.0f);
    const Keyframe k = interpolate(motion, time, [](const Keyframe& a, const Keyframe& b, float t) {
        return Keyframe{0.0f, glm::mix(a.translation, b.translation, t), a.rotationYDegrees + (b.rotationYDegrees - a.rotationYDegrees) * t};
    });
    glm::mat4 m = glm::translate(glm::mat4(1.0f), k.translation);
    return glm::rotate(m, glm::radians(k.rotationYDegrees), glm::vec3(0.0f, 1.0f, 0.0f));
}

CameraKey CameraPath::at(float time) const {
    if (keys.empty()) return CameraKey{};
    return interpolate(keys, time, [](const CameraKey& a, const CameraKey& b, float t) {
        return CameraKey{0.0f, glm::mix(a.position, b.position, t), glm::mix(a.target, b.target, t),
                         glm::normalize(glm::mix(a.up, b.up, t)), a.verticalFovDegrees + (b.verticalFovDegrees - a.verticalFovDegrees) * t};
    });
}

void Scene::validate() const {
    auto fail = [&](const std::string& what) {
        throw Error(ErrorKind::InvalidArgument, "scene '" + name + "': " + what);
    };
    if (meshes.empty()) fail("has no meshes");
    for (const auto& m : materials) {
        if (!finite(m.albedo) || !finite(m.specular) || !finite(m.emission) || !std::isfinite(m.roughness))
            fail("material '" + m.name + "' has a non-finite value");
        if (glm::any(glm::lessThan(m.emission, glm::vec3(0.0f))) || glm::any(glm::lessThan(m.albedo, glm::vec3(0.0f))))
            fail("material '" + m.name + "' has a negative albedo or emission");
        if (m.roughness < 0.0f) fail("material '" + m.name + "' has a negative roughness");
    }
    for (const auto& mesh : meshes) {
        if (mesh.triangles.empty()) fail("mesh '" + mesh.name + "' has no triangles");
        if (mesh.material >= materials.size())
            fail("mesh '" + mesh.name + "' uses material " + std::to_string(mesh.material) + " of " +
                 std::to_string(materials.size()));
        if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
            fail("mesh '" + mesh.name + "' has " + std::to_string(mesh.normals.size()) + " normals for " +
                 std::to_string(mesh.positions.size()) + " positions");
        for (const auto& p : mesh.positions)
            if (!finite(p)) fail("mesh '" + mesh.name + "' has a non-finite vertex position");
        for (const auto& t : mesh.triangles)
            if (t.x >= mesh.positions.size() || t.y >= mesh.positions.size() || t.z >= mesh.positions.size())
                fail("mesh '" + mesh.name + "' has a triangle index past its " + std::to_string(mesh.positions.size()) +
                     " vertices");
    }
    if (camera.keys.empty()) fail("has no camera keys");
    if (framesPerSecond <= 0.0f) fail("framesPerSecond must be positive");
}

} // namespace hush::tracer
