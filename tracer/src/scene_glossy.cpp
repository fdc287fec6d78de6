// "glossy": GGX surfaces over the whole roughness range a denoiser meets, from a
// near mirror (alpha 0.02) to almost diffuse (alpha 0.8), plus perfect mirrors
// (alpha 0), on a matte checker floor lit by an area light and a sky. Glossy
// reflections move with the camera differently from the surfaces that carry
// them, which is what virtual-position reprojection (seed 000 Sec. 3.4) and the
// glossy branch of each chain are tested on.
#include <cmath>
#include <string>

#include "mesh_builders.hpp"

namespace hush::tracer::build {

namespace {

// The GGX alphas of the brief, one sphere each in both rows.
constexpr float kAlphas[] = {0.02f, 0.05f, 0.1f, 0.2f, 0.4f, 0.8f};

std::string alphaName(float alpha) {
    std::string s = std::to_string(alpha);   // "0.020000": trim the trailing zeros
    s.erase(s.find_last_not_of('0') + 1);
    return s;
}

} // namespace

Scene makeGlossyScene() {
    Scene scene;
    scene.name = "glossy";
    scene.sceneScale = 1.0f;   // metres
    scene.framesPerSecond = 30.0f;

    // A high-contrast checker floor so that blurred or lagging reflections show.
    const uint32_t floorLight = addMaterial(scene, matte("floor-light", {0.70f, 0.70f, 0.68f}));
    const uint32_t floorDark = addMaterial(scene, matte("floor-dark", {0.20f, 0.20f, 0.20f}));
    Mesh tilesLight = makeMesh("floor-light", floorLight);
    Mesh tilesDark = makeMesh("floor-dark", floorDark);
    addCheckerRect(tilesLight, tilesDark, {-5, 0, -5}, {10, 0, 0}, {0, 0, 10}, 20, 20, {0, 1, 0});
    scene.meshes.push_back(std::move(tilesLight));
    scene.meshes.push_back(std::move(tilesDark));

    // Perfect mirrors: a sphere at the head of the metal row and a large panel
    // behind both rows, which shows the spheres' backs (a reflection far from the
    // surface it is seen in).
    const uint32_t mirror = addMaterial(scene, metal("mirror", glm::vec3(0.95f), 0.0f));
    const float radius = 0.3f;

    // Front row: a neutral metal (no diffuse part) at each alpha, mirror first.
    Mesh mirrorSphere = makeMesh("metal-sphere-0", mirror);
    addIcosphere(mirrorSphere, {-2.4f, radius, 0.6f}, radius, 3);
    scene.meshes.push_back(std::move(mirrorSphere));
    for (int i = 0; i < 6; ++i) {
        const uint32_t m =
            addMaterial(scene, metal("metal-" + alphaName(kAlphas[i]), {0.91f, 0.92f, 0.92f}, kAlphas[i]));
        Mesh sphere = makeMesh("metal-sphere-" + alphaName(kAlphas[i]), m);
        addIcosphere(sphere, {-1.6f + 0.8f * static_cast<float>(i), radius, 0.6f}, radius, 3);
        scene.meshes.push_back(std::move(sphere));
    }
    // Back row, staggered between the front spheres: a red dielectric (F0 0.04 over
    // a Lambert base) at the same alphas, so both layers of the material show.
    for (int i = 0; i < 6; ++i) {
        const uint32_t m =
            addMaterial(scene, dielectric("plastic-" + alphaName(kAlphas[i]), {0.60f, 0.08f, 0.06f}, kAlphas[i]));
        Mesh sphere = makeMesh("plastic-sphere-" + alphaName(kAlphas[i]), m);
        addIcosphere(sphere, {-2.0f + 0.8f * static_cast<float>(i), radius, -0.6f}, radius, 3);
        scene.meshes.push_back(std::move(sphere));
    }

    // The mirror panel, 1 cm in front of a dark backing board (not coplanar with it).
    const uint32_t board = addMaterial(scene, matte("mirror-backing", {0.05f, 0.05f, 0.05f}));
    Mesh backing = makeMesh("mirror-backing", board);
    addBox(backing, {-3.05f, 0.0f, -1.95f}, {3.05f, 2.25f, -1.81f});
    scene.meshes.push_back(std::move(backing));
    Mesh panel = makeMesh("mirror-panel", mirror);
    addRect(panel, {-3.0f, 0.05f, -1.8f}, {6.0f, 0, 0}, {0, 2.15f, 0}, {0, 0, 1});
    scene.meshes.push_back(std::move(panel));

    // A 1.5 m square area light 3.2 m up, facing down: irradiance about 3 under it,
    // a sharp highlight in the smooth spheres and a broad one in the rough ones.
    const uint32_t light = addMaterial(scene, emitter("area-light", glm::vec3(15.0f, 14.5f, 13.8f)));
    Mesh lamp = makeMesh("area-light", light);
    addRect(lamp, {-0.75f, 3.2f, -0.45f}, {1.5f, 0, 0}, {0, 0, 1.5f}, {0, -1, 0});
    scene.meshes.push_back(std::move(lamp));

    // A dim overcast sky: the reflections of the environment, and light in the
    // shadows, without a sun.
    scene.sky.zenith = {0.15f, 0.22f, 0.40f};
    scene.sky.horizon = {0.40f, 0.45f, 0.50f};
    scene.sky.ground = {0.10f, 0.10f, 0.10f};

    // "orbit": 70 degrees of a circle around the rows in 4 s. Keys every 0.25 s
    // keep the linearly interpolated path within 4 mm of the true arc.
    scene.camera.name = "orbit";
    scene.camera.nearPlane = 0.05f;
    scene.camera.farPlane = 100.0f;
    const glm::vec3 centre(0.0f, 0.4f, -0.3f);
    constexpr float kRadius = 4.5f;
    for (int i = 0; i <= 16; ++i) {
        const float t = 0.25f * static_cast<float>(i);
        const float angle = glm::radians(-35.0f + 70.0f * t / 4.0f);
        const glm::vec3 position = centre + glm::vec3(kRadius * std::sin(angle), 1.1f, kRadius * std::cos(angle));
        scene.camera.keys.push_back(lookToward(t, position, centre, 40.0f));
    }
    return scene;
}

} // namespace hush::tracer::build
