// "thin": foliage-like thin geometry in front of a patterned wall, seen by a camera
// strafing sideways. Grass blades, leaves and fence bars are a few pixels wide,
// so every frame disoccludes and occludes background along thousands of edges,
// and the 1-spp G-buffer alone cannot tell a denoiser which side of a blade a
// pixel's neighbours lie on. Placement is pseudo-random with a fixed seed.
#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "mesh_builders.hpp"

namespace hush::tracer::build {

namespace {

constexpr uint64_t kSeed = 0x7468696E5F736365ull;   // fixed: the scene is the same on every run

glm::vec3 randomUnitVector(Rng& rng) {
    const float z = rng.uniform(-1.0f, 1.0f);
    const float phi = rng.uniform(0.0f, glm::two_pi<float>());
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Blades in a rectangle of ground: random yaw, height, width and lean.
void addGrass(Mesh& a, Mesh& b, Rng& rng, int count) {
    for (int i = 0; i < count; ++i) {
        // One draw per statement: the order of evaluating function arguments is
        // unspecified, and the scene must not depend on the compiler.
        const float x = rng.uniform(-4.5f, 4.5f);
        const float z = rng.uniform(-2.5f, 1.5f);
        const glm::vec3 base(x, 0.0f, z);
        const float yaw = rng.uniform(0.0f, glm::two_pi<float>());
        const float halfWidth = rng.uniform(0.008f, 0.018f);
        const float height = rng.uniform(0.2f, 0.55f);
        const float lean = rng.uniform(0.0f, 0.35f);              // radians from vertical
        const float leanYaw = rng.uniform(0.0f, glm::two_pi<float>());
        const glm::vec3 up = height * glm::vec3(std::sin(lean) * std::cos(leanYaw), std::cos(lean),
                                                std::sin(lean) * std::sin(leanYaw));
        Mesh& target = rng.uniform() < 0.5f ? a : b;
        addCard(target, base, halfWidth * glm::vec3(std::cos(yaw), 0.0f, std::sin(yaw)), up, 0.1f);
    }
}

// Leaves scattered through an ellipsoidal bush, each a small card at a random
// orientation, spread over three greens.
void addBush(Mesh* leafMeshes[3], Rng& rng, glm::vec3 centre, glm::vec3 radii, int count) {
    for (int i = 0; i < count; ++i) {
        glm::vec3 p;
        do {   // rejection keeps the ellipsoid uniformly filled
            p.x = rng.uniform(-1.0f, 1.0f);
            p.y = rng.uniform(-1.0f, 1.0f);
            p.z = rng.uniform(-1.0f, 1.0f);
        } while (glm::dot(p, p) > 1.0f);
        const glm::vec3 n = randomUnitVector(rng);
        const glm::vec3 helper = std::abs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        const glm::vec3 along = glm::normalize(glm::cross(helper, n));
        const glm::vec3 across = glm::cross(n, along);
        const float length = rng.uniform(0.08f, 0.15f);
        const glm::vec3 base = centre + p * radii - 0.5f * length * along;
        const int colour = static_cast<int>(rng.uniform() * 3.0f);
        addCard(*leafMeshes[colour], base, 0.25f * length * across, length * along, 0.3f);
    }
}

} // namespace

Scene makeThinScene() {
    Scene scene;
    scene.name = "thin";
    scene.sceneScale = 1.0f;   // metres
    scene.framesPerSecond = 30.0f;
    Rng rng(kSeed);

    const uint32_t soil = addMaterial(scene, matte("soil", {0.30f, 0.24f, 0.17f}));
    const uint32_t brick = addMaterial(scene, matte("brick", {0.45f, 0.20f, 0.12f}));
    const uint32_t stone = addMaterial(scene, matte("stone", {0.70f, 0.68f, 0.62f}));
    const uint32_t grassA = addMaterial(scene, dielectric("grass-a", {0.15f, 0.38f, 0.07f}, 0.5f));
    const uint32_t grassB = addMaterial(scene, dielectric("grass-b", {0.25f, 0.42f, 0.10f}, 0.5f));
    const uint32_t leafA = addMaterial(scene, dielectric("leaf-a", {0.12f, 0.35f, 0.06f}, 0.35f));
    const uint32_t leafB = addMaterial(scene, dielectric("leaf-b", {0.18f, 0.42f, 0.08f}, 0.35f));
    const uint32_t leafC = addMaterial(scene, dielectric("leaf-c", {0.30f, 0.45f, 0.10f}, 0.35f));
    const uint32_t paint = addMaterial(scene, dielectric("fence-paint", {0.08f, 0.15f, 0.10f}, 0.3f));

    Mesh ground = makeMesh("ground", soil);
    addRect(ground, {-6, 0, -4}, {12, 0, 0}, {0, 0, 9}, {0, 1, 0});
    // The background: a checker of brick and stone, so a disoccluded patch that is
    // filled with the wrong history shows.
    Mesh bricks = makeMesh("wall-brick", brick);
    Mesh stones = makeMesh("wall-stone", stone);
    addCheckerRect(bricks, stones, {-6, 0, -3}, {12, 0, 0}, {0, 3, 0}, 24, 6, {0, 0, 1});

    Mesh grass1 = makeMesh("grass-a", grassA);
    Mesh grass2 = makeMesh("grass-b", grassB);
    addGrass(grass1, grass2, rng, 2000);

    Mesh leaves1 = makeMesh("leaves-a", leafA);
    Mesh leaves2 = makeMesh("leaves-b", leafB);
    Mesh leaves3 = makeMesh("leaves-c", leafC);
    Mesh* leafMeshes[3] = {&leaves1, &leaves2, &leaves3};
    addBush(leafMeshes, rng, {-2.0f, 0.9f, -1.6f}, {0.7f, 0.55f, 0.5f}, 600);
    addBush(leafMeshes, rng, {0.3f, 1.1f, -2.0f}, {0.8f, 0.6f, 0.5f}, 600);
    addBush(leafMeshes, rng, {2.4f, 0.8f, -1.4f}, {0.6f, 0.5f, 0.45f}, 600);

    // A fence nearest the camera: 3 cm bars every 25 cm, the largest parallax.
    Mesh fence = makeMesh("fence", paint);
    for (int i = 0; i <= 32; ++i) {
        const float x = -4.0f + 0.25f * static_cast<float>(i);
        addBox(fence, {x - 0.015f, 0.0f, 0.785f}, {x + 0.015f, 1.3f, 0.815f});
    }
    for (const float y : {0.3f, 1.15f}) addBox(fence, {-4.1f, y, 0.815f}, {4.1f, y + 0.04f, 0.845f});

    for (Mesh* m : {&ground, &bricks, &stones, &grass1, &grass2, &leaves1, &leaves2, &leaves3, &fence})
        scene.meshes.push_back(std::move(*m));

    // Sun from behind the camera's left shoulder, so the faces the camera sees are
    // lit and the shadows of blades and bars fall on the ground and the wall.
    scene.sun.direction = glm::normalize(glm::vec3(0.4f, -0.75f, -0.5f));
    scene.sun.angularRadiusDegrees = 0.27f;
    scene.sun.radiance = glm::vec3(1.0f, 0.95f, 0.88f) * sunRadianceFor(20.0f, scene.sun.angularRadiusDegrees);
    scene.sky.zenith = {0.30f, 0.45f, 0.85f};
    scene.sky.horizon = {0.75f, 0.80f, 0.90f};
    scene.sky.ground = {0.20f, 0.18f, 0.15f};

    // "strafe": 3 m sideways in 4 s at a constant speed, looking straight ahead
    // and a little down, so everything slides across the screen at a speed that
    // depends on its depth.
    scene.camera.name = "strafe";
    scene.camera.nearPlane = 0.05f;
    scene.camera.farPlane = 100.0f;
    for (int i = 0; i <= 4; ++i) {
        const float t = static_cast<float>(i);
        const glm::vec3 position(-1.5f + 0.75f * t, 0.9f, 3.5f);
        scene.camera.keys.push_back(lookToward(t, position, position + glm::vec3(0.0f, -0.15f, -1.0f), 45.0f));
    }
    return scene;
}

} // namespace hush::tracer::build
