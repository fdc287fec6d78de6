#pragma once
// Geometry, material and camera helpers for the procedurally built scenes
// (builtin_scenes.cpp, scene_*.cpp). Internal to the tracer.
//
// Every builder appends to a Mesh and always writes one normal per vertex, so a
// mesh may mix faceted parts (quads, boxes) and smooth ones (spheres) and still
// satisfy Scene::validate (normals empty or one per position). Faceted parts
// duplicate their corner vertices so that each face keeps its own flat normal.
// Winding: triangles are counter-clockwise seen from the side their normal faces.
#include <cstdint>
#include <span>
#include <string>

#include <glm/glm.hpp>

#include <hush/tracer/scene.hpp>

namespace hush::tracer::build {

// A small deterministic generator (SplitMix64): the same seed gives the same
// scene on every platform and standard library, unlike std::rand or the
// implementation-defined std:: distributions.
class Rng {
public:
    explicit Rng(uint64_t seed) : state_(seed) {}
    uint64_t next();
    float uniform();                                       // [0, 1)
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }

private:
    uint64_t state_;
};

Mesh makeMesh(std::string name, uint32_t material);

// Appends triangle/quad with the corners in the given order (counter-clockwise
// seen from the front); the flat normal is the right-handed cross product.
void addTriangle(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c);
void addQuad(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d);

// The same quad, its winding flipped if needed so that its normal points along
// `facing`: scenes state which way a wall faces instead of getting corner order
// right by hand.
void addQuadFacing(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 facing);

// The rectangle origin + s*u + t*v, s,t in [0,1], facing `facing`.
void addRect(Mesh& mesh, glm::vec3 origin, glm::vec3 u, glm::vec3 v, glm::vec3 facing);

// A rectangle with a rectangular opening (a wall with a window), made of the four
// rectangles around the hole; hole bounds are fractions of u and v, in (0,1).
void addRectWithHole(Mesh& mesh, glm::vec3 origin, glm::vec3 u, glm::vec3 v, glm::vec2 holeMin,
                     glm::vec2 holeMax, glm::vec3 facing);

// A rectangle split into nu x nv tiles alternating between two meshes (a checker
// board): visible texture makes blur, lag and ghosting show in reflections and
// disocclusions, which a uniform colour would hide.
void addCheckerRect(Mesh& even, Mesh& odd, glm::vec3 origin, glm::vec3 u, glm::vec3 v, int nu, int nv,
                    glm::vec3 facing);

// Axis-aligned box with outward faces (12 triangles).
void addBox(Mesh& mesh, glm::vec3 min, glm::vec3 max);

// A vertical prism: the footprint polygon (x,z corners in order around it, either
// direction) extruded from y0 to y1, with outward faces, top and bottom. Builds the
// Cornell boxes, whose footprints are rotated and not exactly rectangular.
void addPrism(Mesh& mesh, std::span<const glm::vec2> footprintXZ, float y0, float y1);

// Icosahedron subdivided `subdivisions` times (20 * 4^n triangles) with smooth
// outward normals: more even than a latitude-longitude sphere, no pole clusters.
void addIcosphere(Mesh& mesh, glm::vec3 centre, float radius, int subdivisions);

// Cylinder along +Y from baseCentre, smooth sides, flat caps.
void addCylinder(Mesh& mesh, glm::vec3 baseCentre, float radius, float height, int segments);

// A thin card (grass blade, leaf): a quad from `base` spanning +-halfWidth at the
// base and `up` to the tip, where the width is scaled by tipScale; tipScale <= 0
// gives a pointed triangle (a quad would have a degenerate, zero-area half).
void addCard(Mesh& mesh, glm::vec3 base, glm::vec3 halfWidth, glm::vec3 up, float tipScale);

// Materials (the realistic ranges of the brief: albedo <= 0.9, dielectric F0 0.04,
// metals with coloured F0 and no diffuse part).
Material matte(std::string name, glm::vec3 albedo);
Material dielectric(std::string name, glm::vec3 albedo, float roughness);
Material metal(std::string name, glm::vec3 f0, float roughness);
Material emitter(std::string name, glm::vec3 radiance);

// Appends a material and returns its index.
uint32_t addMaterial(Scene& scene, Material material);

// A camera key at `position` looking towards `point`. The target is stored one
// unit along the view direction, so that linear interpolation of position and
// target between keys interpolates the view direction itself, independent of
// how far the camera moves.
CameraKey lookToward(float time, glm::vec3 position, glm::vec3 point, float verticalFovDegrees);

// Sun radiance giving `irradiance` on a surface facing it, for a disc of the given
// angular radius (radiance times the disc's solid angle 2 pi (1 - cos r)).
float sunRadianceFor(float irradiance, float angularRadiusDegrees);

// One factory per scene_*.cpp; builtin_scenes.cpp maps the names to them.
Scene makeCornellScene();
Scene makeRoomScene();
Scene makeGlossyScene();
Scene makeMovingLightScene();
Scene makeThinScene();

} // namespace hush::tracer::build
