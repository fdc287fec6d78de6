#pragma once
// Small scenes made in the tests themselves, so that each test knows exactly what
// it renders: a floor, two boxes, a back wall and a quad light.
#include <hush/tracer/scene.hpp>

namespace hush::tracer::test {

inline void addQuad(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    const uint32_t base = uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c, d});
    mesh.triangles.push_back(glm::uvec3(base, base + 1, base + 2));
    mesh.triangles.push_back(glm::uvec3(base, base + 2, base + 3));
}

inline Mesh box(const std::string& name, glm::vec3 lo, glm::vec3 hi, uint32_t material) {
    Mesh m;
    m.name = name;
    m.material = material;
    const glm::vec3 p[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                            {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    addQuad(m, p[0], p[1], p[2], p[3]);
    addQuad(m, p[4], p[7], p[6], p[5]);
    addQuad(m, p[0], p[4], p[5], p[1]);
    addQuad(m, p[3], p[2], p[6], p[7]);
    addQuad(m, p[0], p[3], p[7], p[4]);
    addQuad(m, p[1], p[5], p[6], p[2]);
    return m;
}

// `moving`: the camera slides and turns over the first second (30 frames).
inline Scene tabletop(bool moving) {
    Scene s;
    s.name = "tabletop";
    Material floor{"floor", glm::vec3(0.7f), glm::vec3(0.0f), 0.5f, glm::vec3(0.0f)};
    Material red{"red", glm::vec3(0.7f, 0.15f, 0.1f), glm::vec3(0.04f), 0.3f, glm::vec3(0.0f)};
    Material metal{"metal", glm::vec3(0.0f), glm::vec3(0.9f, 0.8f, 0.6f), 0.2f, glm::vec3(0.0f)};
    Material light{"light", glm::vec3(0.0f), glm::vec3(0.0f), 0.5f, glm::vec3(12.0f)};
    s.materials = {floor, red, metal, light};
    Mesh ground;
    ground.name = "floor";
    addQuad(ground, {-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4});
    Mesh wall;
    wall.name = "wall";
    addQuad(wall, {-4, 0, -2}, {4, 0, -2}, {4, 4, -2}, {-4, 4, -2});
    Mesh lamp;
    lamp.name = "lamp";
    lamp.material = 3;
    addQuad(lamp, {-0.5f, 3, -0.5f}, {0.5f, 3, -0.5f}, {0.5f, 3, 0.5f}, {-0.5f, 3, 0.5f});
    s.meshes = {ground, wall, box("red box", {-1.2f, 0, -0.8f}, {-0.2f, 1.0f, 0.2f}, 1),
                box("metal box", {0.4f, 0, -0.4f}, {1.2f, 1.6f, 0.4f}, 2), lamp};
    s.sky.zenith = glm::vec3(0.2f, 0.3f, 0.5f);
    s.sky.horizon = glm::vec3(0.4f);
    CameraKey a{0.0f, {0.0f, 1.5f, 5.0f}, {0.0f, 0.8f, 0.0f}, {0, 1, 0}, 45.0f};
    CameraKey b = a;
    b.time = 1.0f;
    if (moving) {
        b.position = {3.0f, 2.2f, 3.8f};   // a brisk move: pixels per frame, not fractions
        b.target = {0.8f, 0.6f, 0.0f};
    }
    s.camera.name = moving ? "slide" : "still";
    s.camera.keys = {a, b};
    s.camera.nearPlane = 0.1f;
    s.camera.farPlane = 100.0f;
    return s;
}

} // namespace hush::tracer::test
