// "room": a closed 6 x 3 x 5 m room lit through one window by a sun and a sky, so
// that the image is mostly indirect light bounced from a bright sun patch on the
// floor: the setting Mara et al. (seed 000, Sec. 4) denoise. A glossy floor, a
// gold sphere, a glazed vase and a chrome ball give the glossy branch work.
#include "mesh_builders.hpp"

namespace hush::tracer::build {

namespace {

// Room interior: x in [-3, 3], y in [0, 3] (floor to ceiling), z in [-2.5, 2.5].
constexpr float kHalfX = 3.0f, kHeight = 3.0f, kHalfZ = 2.5f;
// The window in the x = -3 wall: z in [-1.5, 0.5], y in [0.8, 2.4], in a wall
// 0.25 m thick (the reveal shades the edges of the sun patch, as a real one does).
constexpr float kWinZ0 = -1.5f, kWinZ1 = 0.5f, kWinY0 = 0.8f, kWinY1 = 2.4f, kWall = 0.25f;

void addWindowWall(Mesh& wall, Mesh& frame) {
    const glm::vec3 inward(1, 0, 0);
    const float x = -kHalfX, xo = -kHalfX - kWall;
    addRectWithHole(wall, {x, 0, -kHalfZ}, {0, 0, 2 * kHalfZ}, {0, kHeight, 0},
                    {(kWinZ0 + kHalfZ) / (2 * kHalfZ), kWinY0 / kHeight},
                    {(kWinZ1 + kHalfZ) / (2 * kHalfZ), kWinY1 / kHeight}, inward);
    // The reveal: sill, head and jambs spanning the wall's thickness, facing the
    // opening. Nothing else is built outside: light enters only through the hole.
    const glm::vec3 depth(x - xo, 0, 0);
    addRect(wall, {xo, kWinY0, kWinZ0}, depth, {0, 0, kWinZ1 - kWinZ0}, {0, 1, 0});
    addRect(wall, {xo, kWinY1, kWinZ0}, depth, {0, 0, kWinZ1 - kWinZ0}, {0, -1, 0});
    addRect(wall, {xo, kWinY0, kWinZ0}, depth, {0, kWinY1 - kWinY0, 0}, {0, 0, 1});
    addRect(wall, {xo, kWinY0, kWinZ1}, depth, {0, kWinY1 - kWinY0, 0}, {0, 0, -1});
    // A cross of mullions: thin shadows inside the sun patch (fine detail that a
    // denoiser must not blur away).
    const float mx0 = xo + 0.06f, mx1 = xo + 0.13f, zc = 0.5f * (kWinZ0 + kWinZ1), yc = 0.5f * (kWinY0 + kWinY1);
    addBox(frame, {mx0, kWinY0, zc - 0.03f}, {mx1, kWinY1, zc + 0.03f});
    addBox(frame, {mx0, yc - 0.03f, kWinZ0}, {mx1, yc + 0.03f, kWinZ1});
}

} // namespace

Scene makeRoomScene() {
    Scene scene;
    scene.name = "room";
    scene.sceneScale = 1.0f;   // metres
    scene.framesPerSecond = 30.0f;

    const uint32_t plaster = addMaterial(scene, matte("plaster", {0.75f, 0.72f, 0.66f}));
    const uint32_t ceilingPaint = addMaterial(scene, matte("ceiling", {0.80f, 0.80f, 0.78f}));
    const uint32_t wood = addMaterial(scene, dielectric("varnished-floor", {0.42f, 0.28f, 0.16f}, 0.25f));
    const uint32_t framePaint = addMaterial(scene, dielectric("window-frame", {0.80f, 0.80f, 0.78f}, 0.4f));
    const uint32_t rugFabric = addMaterial(scene, matte("rug", {0.50f, 0.15f, 0.12f}));
    const uint32_t tableWood = addMaterial(scene, dielectric("table", {0.30f, 0.18f, 0.10f}, 0.3f));
    const uint32_t sofaFabric = addMaterial(scene, matte("sofa", {0.25f, 0.35f, 0.55f}));
    const uint32_t shelfWood = addMaterial(scene, matte("bookshelf", {0.55f, 0.45f, 0.35f}));
    const uint32_t cabinetPaint = addMaterial(scene, dielectric("cabinet", {0.60f, 0.20f, 0.15f}, 0.5f));
    const uint32_t gold = addMaterial(scene, metal("gold", {0.95f, 0.70f, 0.30f}, 0.15f));
    const uint32_t glaze = addMaterial(scene, dielectric("vase-glaze", {0.10f, 0.35f, 0.40f}, 0.05f));
    const uint32_t chrome = addMaterial(scene, metal("chrome", {0.55f, 0.56f, 0.55f}, 0.05f));

    // The shell: every surface faces into the room.
    Mesh floor = makeMesh("floor", wood);
    addRect(floor, {-kHalfX, 0, -kHalfZ}, {2 * kHalfX, 0, 0}, {0, 0, 2 * kHalfZ}, {0, 1, 0});
    Mesh ceiling = makeMesh("ceiling", ceilingPaint);
    addRect(ceiling, {-kHalfX, kHeight, -kHalfZ}, {2 * kHalfX, 0, 0}, {0, 0, 2 * kHalfZ}, {0, -1, 0});
    Mesh walls = makeMesh("walls", plaster);
    addRect(walls, {-kHalfX, 0, -kHalfZ}, {2 * kHalfX, 0, 0}, {0, kHeight, 0}, {0, 0, 1});    // back
    addRect(walls, {-kHalfX, 0, kHalfZ}, {2 * kHalfX, 0, 0}, {0, kHeight, 0}, {0, 0, -1});    // front
    addRect(walls, {kHalfX, 0, -kHalfZ}, {0, 0, 2 * kHalfZ}, {0, kHeight, 0}, {-1, 0, 0});    // right
    Mesh frame = makeMesh("window-frame", framePaint);
    addWindowWall(walls, frame);

    // A rug lying partly in the sun patch: its red bleeds onto the walls and
    // ceiling, which only the indirect light carries.
    Mesh rug = makeMesh("rug", rugFabric);
    addBox(rug, {-2.0f, 0.0f, -0.8f}, {-0.4f, 0.012f, 1.2f});

    Mesh table = makeMesh("table", tableWood);
    addBox(table, {0.2f, 0.72f, -1.2f}, {1.6f, 0.77f, -0.4f});
    for (const float lx : {0.25f, 1.50f})
        for (const float lz : {-1.15f, -0.50f}) addBox(table, {lx, 0.0f, lz}, {lx + 0.05f, 0.72f, lz + 0.05f});

    Mesh sofa = makeMesh("sofa", sofaFabric);
    addBox(sofa, {-0.5f, 0.0f, 1.6f}, {1.7f, 0.42f, 2.45f});     // seat
    addBox(sofa, {-0.5f, 0.42f, 2.2f}, {1.7f, 0.85f, 2.45f});    // back
    addBox(sofa, {-0.5f, 0.42f, 1.6f}, {-0.3f, 0.62f, 2.2f});    // arms
    addBox(sofa, {1.5f, 0.42f, 1.6f}, {1.7f, 0.62f, 2.2f});
    Mesh shelf = makeMesh("bookshelf", shelfWood);
    addBox(shelf, {1.6f, 0.0f, -2.5f}, {2.8f, 2.0f, -2.15f});
    Mesh cabinet = makeMesh("cabinet", cabinetPaint);
    addBox(cabinet, {2.5f, 0.0f, -0.5f}, {3.0f, 0.9f, 1.0f});

    // The glossy objects: low roughness, so their reflections move differently
    // from the surfaces under them (seed 000 Sec. 3.4).
    Mesh sphere = makeMesh("gold-sphere", gold);
    addIcosphere(sphere, {0.6f, 0.77f + 0.12f, -0.8f}, 0.12f, 3);
    Mesh vase = makeMesh("vase", glaze);
    addCylinder(vase, {1.2f, 0.77f, -0.75f}, 0.08f, 0.30f, 24);
    Mesh ball = makeMesh("chrome-ball", chrome);
    addIcosphere(ball, {-1.0f, 0.2f, -1.5f}, 0.2f, 3);

    for (Mesh* m : {&floor, &ceiling, &walls, &frame, &rug, &table, &sofa, &shelf, &cabinet, &sphere, &vase, &ball})
        scene.meshes.push_back(std::move(*m));

    // The sun enters the window downwards and slightly towards +Z, laying a patch
    // on the floor around x in [-2.2, -0.6]. 30 units of irradiance against a sky of
    // about 1 unit of radiance: a clear day's ratio, so the patch dominates.
    scene.sun.direction = glm::normalize(glm::vec3(0.62f, -0.62f, 0.2f));
    scene.sun.angularRadiusDegrees = 0.27f;
    scene.sun.radiance = glm::vec3(1.0f, 0.95f, 0.88f) * sunRadianceFor(30.0f, scene.sun.angularRadiusDegrees);
    scene.sky.zenith = {0.30f, 0.45f, 0.85f};
    scene.sky.horizon = {0.75f, 0.80f, 0.90f};
    scene.sky.ground = {0.25f, 0.22f, 0.18f};

    // "walk": 4 s along the room at eye height (with a slight bob) from the
    // cabinet side towards the sofa, turning from the sun patch to the window.
    scene.camera.name = "walk";
    scene.camera.nearPlane = 0.05f;
    scene.camera.farPlane = 50.0f;
    const glm::vec3 positions[] = {{2.2f, 1.60f, 1.30f}, {1.7f, 1.62f, 1.15f}, {1.1f, 1.60f, 1.00f},
                                   {0.55f, 1.62f, 0.90f}, {0.0f, 1.60f, 0.85f}};
    const glm::vec3 looks[] = {{-1.4f, 0.3f, 0.2f}, {-1.5f, 0.4f, 0.0f}, {-1.6f, 0.6f, -0.4f},
                               {-1.8f, 0.8f, -1.0f}, {-2.0f, 1.0f, -1.6f}};
    for (int i = 0; i < 5; ++i)
        scene.camera.keys.push_back(lookToward(static_cast<float>(i), positions[i], looks[i], 55.0f));
    return scene;
}

} // namespace hush::tracer::build
