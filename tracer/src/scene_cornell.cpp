// "cornell": the classic Cornell box of ../shared/scenes/cbox/README.md, built in
// code with the same coordinates (millimetres) as the published OBJ meshes, and
// the README's materials, emitter and camera. The OBJ loader renders the files
// themselves; this scene exists so the box needs no external data and gets an
// animated camera path.
#include <array>
#include <cmath>

#include "mesh_builders.hpp"

namespace hush::tracer::build {

Scene makeCornellScene() {
    Scene scene;
    scene.name = "cornell";
    scene.sceneScale = 0.001f;   // millimetres, as the reference meshes
    scene.framesPerSecond = 30.0f;

    // Diffuse reflectances and the emitter radiance of the README's table.
    const uint32_t white = addMaterial(scene, matte("white", {0.885809f, 0.698859f, 0.666422f}));
    const uint32_t red = addMaterial(scene, matte("red", {0.570068f, 0.0430135f, 0.0443706f}));
    const uint32_t green = addMaterial(scene, matte("green", {0.105421f, 0.37798f, 0.076425f}));
    const uint32_t box = addMaterial(scene, matte("box", {0.45f, 0.30f, 0.90f}));
    Material lightMaterial = matte("light", {0.936461f, 0.740433f, 0.705267f});
    lightMaterial.emission = {18.387f, 10.9873f, 2.75357f};
    const uint32_t light = addMaterial(scene, lightMaterial);

    // The box is not quite rectangular: the floor and the red wall are skewed by a
    // few millimetres in the reference, and those numbers are kept. Every surface
    // faces into the box. A quad is split along the same diagonal (first to third
    // corner) as the OBJ loader splits the reference faces, so the skewed,
    // slightly non-planar red wall is the same surface.
    const glm::vec3 up(0, 1, 0), down(0, -1, 0);
    Mesh floor = makeMesh("cbox_floor", white);
    addQuadFacing(floor, {552.8f, 0, 0}, {0, 0, 0}, {0, 0, 559.2f}, {549.6f, 0, 559.2f}, up);
    Mesh ceiling = makeMesh("cbox_ceiling", white);
    addQuadFacing(ceiling, {556, 548.8f, 0}, {556, 548.8f, 559.2f}, {0, 548.8f, 559.2f}, {0, 548.8f, 0}, down);
    // The reference ceiling also has an upward-facing patch over the luminaire,
    // coplanar with the ceiling and outside the box; it is never seen and a
    // coplanar duplicate only invites self-intersection, so it is left out.
    Mesh back = makeMesh("cbox_back", white);
    addQuadFacing(back, {549.6f, 0, 559.2f}, {0, 0, 559.2f}, {0, 548.8f, 559.2f}, {556, 548.8f, 559.2f},
                  {0, 0, -1});
    Mesh greenWall = makeMesh("cbox_greenwall", green);
    addQuadFacing(greenWall, {0, 0, 559.2f}, {0, 0, 0}, {0, 548.8f, 0}, {0, 548.8f, 559.2f}, {1, 0, 0});
    Mesh redWall = makeMesh("cbox_redwall", red);
    addQuadFacing(redWall, {552.8f, 0, 0}, {549.6f, 0, 559.2f}, {556, 548.8f, 559.2f}, {556, 548.8f, 0},
                  {-1, 0, 0});

    // The two boxes: rotated footprints on the floor, extruded to their heights.
    const std::array<glm::vec2, 4> smallFootprint{glm::vec2{130, 65}, glm::vec2{82, 225}, glm::vec2{240, 272},
                                                  glm::vec2{290, 114}};
    Mesh smallBox = makeMesh("cbox_smallbox", box);
    addPrism(smallBox, smallFootprint, 0.0f, 165.0f);
    const std::array<glm::vec2, 4> largeFootprint{glm::vec2{423, 247}, glm::vec2{265, 296}, glm::vec2{314, 456},
                                                  glm::vec2{472, 406}};
    Mesh largeBox = makeMesh("cbox_largebox", box);
    addPrism(largeBox, largeFootprint, 0.0f, 330.0f);

    // The luminaire: 130 x 105 mm at the ceiling, moved down 0.5 mm (README) so it
    // does not coincide with the ceiling; it faces down into the box.
    const float ly = 548.8f - 0.5f;
    Mesh luminaire = makeMesh("cbox_luminaire", light);
    addQuadFacing(luminaire, {343, ly, 227}, {343, ly, 332}, {213, ly, 332}, {213, ly, 227}, down);

    for (Mesh* m : {&floor, &ceiling, &back, &greenWall, &redWall, &smallBox, &largeBox, &luminaire})
        scene.meshes.push_back(std::move(*m));

    // No sun, no sky: the box is lit by its luminaire alone, as in the reference.

    // "dolly-pan": starts exactly at the README camera, then trucks 120 mm sideways
    // (+X, to the viewer's left) and 50 mm forward over 2 s while panning 5 degrees
    // back towards the box's centre. The sideways parallax moves the boxes against
    // the back wall, so motion vectors vary with depth and the wall behind the
    // boxes is disoccluded.
    scene.camera.name = "dolly-pan";
    scene.camera.nearPlane = 10.0f;
    scene.camera.farPlane = 2800.0f;
    const glm::vec3 start(278.0f, 273.0f, -800.0f);
    constexpr float kVerticalFov = 39.3077f;
    for (int i = 0; i <= 4; ++i) {
        const float t = 0.5f * static_cast<float>(i);   // 0 .. 2 s
        const float s = t / 2.0f;
        const glm::vec3 position = start + glm::vec3(120.0f * s, 0.0f, 50.0f * s);
        const float pan = glm::radians(-5.0f * s);        // turning towards -X
        const glm::vec3 look = position + glm::vec3(std::sin(pan), 0.0f, std::cos(pan));
        scene.camera.keys.push_back(lookToward(t, position, look, kVerticalFov));
    }
    return scene;
}

} // namespace hush::tracer::build
