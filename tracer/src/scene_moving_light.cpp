// "moving-light": a static camera and a small emissive sphere weaving between
// pillars in an open-fronted diffuse box. Nothing moves on screen but the light,
// its shadows and its bounce light, so motion vectors are zero everywhere and a
// temporal filter that trusts its history shows lag and ghosting here.
#include "mesh_builders.hpp"

namespace hush::tracer::build {

Scene makeMovingLightScene() {
    Scene scene;
    scene.name = "moving-light";
    scene.sceneScale = 1.0f;   // metres
    scene.framesPerSecond = 30.0f;

    const uint32_t floorMat = addMaterial(scene, matte("floor", {0.65f, 0.65f, 0.62f}));
    const uint32_t wallMat = addMaterial(scene, matte("wall", {0.70f, 0.70f, 0.70f}));
    const uint32_t leftMat = addMaterial(scene, matte("left-wall", {0.60f, 0.22f, 0.18f}));
    const uint32_t rightMat = addMaterial(scene, matte("right-wall", {0.18f, 0.32f, 0.55f}));
    const uint32_t pillarMat = addMaterial(scene, matte("pillars", {0.55f, 0.50f, 0.45f}));
    const uint32_t crateMat = addMaterial(scene, matte("crate", {0.50f, 0.55f, 0.35f}));
    const uint32_t ballMat = addMaterial(scene, matte("ball", {0.70f, 0.70f, 0.70f}));
    const uint32_t benchMat = addMaterial(scene, matte("bench", {0.40f, 0.30f, 0.25f}));
    const uint32_t lightMat = addMaterial(scene, emitter("moving-light", {300.0f, 255.0f, 180.0f}));

    // A 6 x 3 x 6 m box open towards the camera (+Z); faces point inwards.
    Mesh floor = makeMesh("floor", floorMat);
    addRect(floor, {-3, 0, -3}, {6, 0, 0}, {0, 0, 6}, {0, 1, 0});
    Mesh shell = makeMesh("back-and-ceiling", wallMat);
    addRect(shell, {-3, 0, -3}, {6, 0, 0}, {0, 3, 0}, {0, 0, 1});
    addRect(shell, {-3, 3, -3}, {6, 0, 0}, {0, 0, 6}, {0, -1, 0});
    // Coloured side walls: the light's colour bleeding changes as it moves.
    Mesh left = makeMesh("left-wall", leftMat);
    addRect(left, {-3, 0, -3}, {0, 0, 6}, {0, 3, 0}, {1, 0, 0});
    Mesh right = makeMesh("right-wall", rightMat);
    addRect(right, {3, 0, -3}, {0, 0, 6}, {0, 3, 0}, {-1, 0, 0});

    // Occluders: a row of pillars the light passes in front of and behind (hard
    // shadows sweeping across the floor and back wall), a crate, a ball and a bench.
    Mesh pillars = makeMesh("pillars", pillarMat);
    for (const float x : {-1.8f, -0.6f, 0.6f, 1.8f})
        addBox(pillars, {x - 0.15f, 0.0f, -0.75f}, {x + 0.15f, 2.2f, -0.45f});
    Mesh crate = makeMesh("crate", crateMat);
    addBox(crate, {-1.6f, 0.0f, 0.6f}, {-0.8f, 0.6f, 1.4f});
    Mesh ball = makeMesh("ball", ballMat);
    addIcosphere(ball, {1.2f, 0.4f, 1.0f}, 0.4f, 3);
    Mesh bench = makeMesh("bench", benchMat);
    addBox(bench, {-2.0f, 0.0f, -2.3f}, {2.0f, 0.5f, -2.0f});

    // The light: a sphere of radius 8 cm built at the origin and placed by its
    // motion keys. Radiance 300 gives about 1.5 units of irradiance at 2 m.
    Mesh light = makeMesh("moving-light", lightMat);
    addIcosphere(light, glm::vec3(0.0f), 0.08f, 2);
    // Left to right in 4 s, slowly rising, zig-zagging in front of (z = 0.3) and
    // behind (z = -1.5) the pillar row at z = -0.6 through the gaps between the
    // pillars; the straight segments between keys clear every pillar.
    constexpr float kSide[] = {0.0f, 1.0f, 0.0f, -1.0f};   // exact, unlike sin(i pi / 2)
    for (int i = 0; i <= 8; ++i) {
        const float t = 0.5f * static_cast<float>(i);
        const float side = kSide[i % 4];
        light.motion.push_back(Keyframe{.time = t,
                                        .translation = {-2.4f + 0.6f * static_cast<float>(i),
                                                        0.8f + 0.3f * t / 4.0f, -0.6f + 0.9f * side},
                                        .rotationYDegrees = 0.0f});
    }

    for (Mesh* m : {&floor, &shell, &left, &right, &pillars, &crate, &ball, &bench, &light})
        scene.meshes.push_back(std::move(*m));

    // No sun and no sky: the moving sphere is the only light, so every pixel's
    // history goes stale as it moves.

    // "static": every key the same, spanning the light's 4 s of motion.
    scene.camera.name = "static";
    scene.camera.nearPlane = 0.05f;
    scene.camera.farPlane = 100.0f;
    const glm::vec3 eye(0.0f, 1.7f, 5.5f), look(0.0f, 0.8f, -0.5f);
    scene.camera.keys.push_back(lookToward(0.0f, eye, look, 45.0f));
    scene.camera.keys.push_back(lookToward(4.0f, eye, look, 45.0f));
    return scene;
}

} // namespace hush::tracer::build
