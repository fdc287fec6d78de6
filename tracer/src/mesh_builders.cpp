#include "mesh_builders.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <glm/gtc/constants.hpp>

#include <hush/core/error.hpp>

namespace hush::tracer::build {

namespace {

uint32_t vertex(Mesh& mesh, glm::vec3 p, glm::vec3 n) {
    mesh.positions.push_back(p);
    mesh.normals.push_back(n);
    return static_cast<uint32_t>(mesh.positions.size() - 1);
}

// Flat triangle/quad whose normal is made to point along `facing`.
void addTriangleFacing(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 facing) {
    if (glm::dot(glm::cross(b - a, c - a), facing) < 0.0f) std::swap(b, c);
    addTriangle(mesh, a, b, c);
}

// Smooth triangle over existing vertices, wound so that its face normal agrees
// with `outward` (builders state the outside instead of tracking index order).
void smoothTriangle(Mesh& mesh, uint32_t i0, uint32_t i1, uint32_t i2, glm::vec3 outward) {
    const auto& p = mesh.positions;
    if (glm::dot(glm::cross(p[i1] - p[i0], p[i2] - p[i0]), outward) < 0.0f) std::swap(i1, i2);
    mesh.triangles.emplace_back(i0, i1, i2);
}

} // namespace

uint64_t Rng::next() {
    state_ += 0x9E3779B97F4A7C15ull;
    uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

float Rng::uniform() {
    // The top 24 bits fill a float's mantissa exactly: uniform on [0, 1), never 1.
    return static_cast<float>(next() >> 40) * (1.0f / 16777216.0f);
}

Mesh makeMesh(std::string name, uint32_t material) {
    Mesh mesh;
    mesh.name = std::move(name);
    mesh.material = material;
    return mesh;
}

void addTriangle(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    const uint32_t i = vertex(mesh, a, n);
    vertex(mesh, b, n);
    vertex(mesh, c, n);
    mesh.triangles.emplace_back(i, i + 1, i + 2);
}

void addQuad(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    // The diagonals' cross product is the normal of a planar quad and stays well
    // defined when one edge is degenerate.
    const glm::vec3 n = glm::normalize(glm::cross(c - a, d - b));
    const uint32_t i = vertex(mesh, a, n);
    vertex(mesh, b, n);
    vertex(mesh, c, n);
    vertex(mesh, d, n);
    mesh.triangles.emplace_back(i, i + 1, i + 2);
    mesh.triangles.emplace_back(i, i + 2, i + 3);
}

void addQuadFacing(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 facing) {
    if (glm::dot(glm::cross(c - a, d - b), facing) < 0.0f)
        addQuad(mesh, a, d, c, b);
    else
        addQuad(mesh, a, b, c, d);
}

void addRect(Mesh& mesh, glm::vec3 origin, glm::vec3 u, glm::vec3 v, glm::vec3 facing) {
    addQuadFacing(mesh, origin, origin + u, origin + u + v, origin + v, facing);
}

void addRectWithHole(Mesh& mesh, glm::vec3 origin, glm::vec3 u, glm::vec3 v, glm::vec2 holeMin,
                     glm::vec2 holeMax, glm::vec3 facing) {
    if (!(holeMin.x > 0.0f && holeMin.y > 0.0f && holeMax.x < 1.0f && holeMax.y < 1.0f &&
          holeMin.x < holeMax.x && holeMin.y < holeMax.y))
        throw Error(ErrorKind::InvalidArgument, "addRectWithHole: the hole must lie strictly inside the rectangle");
    auto part = [&](float s0, float t0, float s1, float t1) {
        addRect(mesh, origin + s0 * u + t0 * v, (s1 - s0) * u, (t1 - t0) * v, facing);
    };
    part(0.0f, 0.0f, 1.0f, holeMin.y);                 // below the hole, full width
    part(0.0f, holeMax.y, 1.0f, 1.0f);                 // above it, full width
    part(0.0f, holeMin.y, holeMin.x, holeMax.y);       // beside it
    part(holeMax.x, holeMin.y, 1.0f, holeMax.y);
}

void addCheckerRect(Mesh& even, Mesh& odd, glm::vec3 origin, glm::vec3 u, glm::vec3 v, int nu, int nv,
                    glm::vec3 facing) {
    const glm::vec3 du = u / static_cast<float>(nu);
    const glm::vec3 dv = v / static_cast<float>(nv);
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i)
            addRect((i + j) % 2 == 0 ? even : odd, origin + static_cast<float>(i) * du + static_cast<float>(j) * dv,
                    du, dv, facing);
}

void addBox(Mesh& mesh, glm::vec3 lo, glm::vec3 hi) {
    const std::array<glm::vec2, 4> footprint{glm::vec2(lo.x, lo.z), glm::vec2(hi.x, lo.z), glm::vec2(hi.x, hi.z),
                                             glm::vec2(lo.x, hi.z)};
    addPrism(mesh, footprint, lo.y, hi.y);
}

void addPrism(Mesh& mesh, std::span<const glm::vec2> footprintXZ, float y0, float y1) {
    const size_t n = footprintXZ.size();
    if (n < 3) throw Error(ErrorKind::InvalidArgument, "addPrism: a footprint needs at least 3 corners");
    glm::vec2 centre(0.0f);
    for (const auto& c : footprintXZ) centre += c;
    centre /= static_cast<float>(n);
    auto at = [&](size_t i, float y) { return glm::vec3(footprintXZ[i].x, y, footprintXZ[i].y); };
    for (size_t i = 0; i < n; ++i) {
        const size_t j = (i + 1) % n;
        const glm::vec2 mid = 0.5f * (footprintXZ[i] + footprintXZ[j]) - centre;
        addQuadFacing(mesh, at(i, y0), at(j, y0), at(j, y1), at(i, y1), glm::vec3(mid.x, 0.0f, mid.y));
    }
    // Caps as fans from corner 0: footprints are convex.
    for (size_t i = 1; i + 1 < n; ++i) {
        addTriangleFacing(mesh, at(0, y1), at(i, y1), at(i + 1, y1), glm::vec3(0.0f, 1.0f, 0.0f));
        addTriangleFacing(mesh, at(0, y0), at(i, y0), at(i + 1, y0), glm::vec3(0.0f, -1.0f, 0.0f));
    }
}

void addIcosphere(Mesh& mesh, glm::vec3 centre, float radius, int subdivisions) {
    // The regular icosahedron: the cyclic permutations of (0, +-1, +-phi).
    const float phi = (1.0f + std::sqrt(5.0f)) * 0.5f;
    std::vector<glm::vec3> points = {
        {-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0}, {0, -1, phi}, {0, 1, phi},
        {0, -1, -phi}, {0, 1, -phi}, {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
    for (auto& p : points) p = glm::normalize(p);
    std::vector<glm::uvec3> faces = {
        {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
        {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (int level = 0; level < subdivisions; ++level) {
        // Shared edge midpoints keep the surface watertight.
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const std::pair<uint32_t, uint32_t> key{std::min(a, b), std::max(a, b)};
            const auto [it, inserted] = midpoints.try_emplace(key, static_cast<uint32_t>(points.size()));
            if (inserted) points.push_back(glm::normalize(points[a] + points[b]));
            return it->second;
        };
        std::vector<glm::uvec3> finer;
        finer.reserve(faces.size() * 4);
        for (const auto& f : faces) {
            const uint32_t ab = midpoint(f.x, f.y), bc = midpoint(f.y, f.z), ca = midpoint(f.z, f.x);
            finer.emplace_back(f.x, ab, ca);
            finer.emplace_back(f.y, bc, ab);
            finer.emplace_back(f.z, ca, bc);
            finer.emplace_back(ab, bc, ca);
        }
        faces = std::move(finer);
    }
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    for (const auto& p : points) vertex(mesh, centre + radius * p, p);
    for (const auto& f : faces)
        smoothTriangle(mesh, base + f.x, base + f.y, base + f.z, points[f.x] + points[f.y] + points[f.z]);
}

void addCylinder(Mesh& mesh, glm::vec3 baseCentre, float radius, float height, int segments) {
    const glm::vec3 top = baseCentre + glm::vec3(0.0f, height, 0.0f);
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    for (int i = 0; i < segments; ++i) {
        const float a = 2.0f * glm::pi<float>() * static_cast<float>(i) / static_cast<float>(segments);
        const glm::vec3 n(std::cos(a), 0.0f, std::sin(a));
        vertex(mesh, baseCentre + radius * n, n);
        vertex(mesh, top + radius * n, n);
    }
    for (int i = 0; i < segments; ++i) {
        const uint32_t b0 = base + 2 * static_cast<uint32_t>(i);
        const uint32_t b1 = base + 2 * static_cast<uint32_t>((i + 1) % segments);
        const glm::vec3 outward = mesh.normals[b0] + mesh.normals[b1];
        smoothTriangle(mesh, b0, b1, b1 + 1, outward);
        smoothTriangle(mesh, b0, b1 + 1, b0 + 1, outward);
    }
    // Caps get their own vertices: their normals differ from the sides'.
    for (const float sign : {-1.0f, 1.0f}) {
        const glm::vec3 n(0.0f, sign, 0.0f);
        const glm::vec3 c = sign > 0.0f ? top : baseCentre;
        const uint32_t centre = vertex(mesh, c, n);
        for (int i = 0; i < segments; ++i) {
            const float a = 2.0f * glm::pi<float>() * static_cast<float>(i) / static_cast<float>(segments);
            vertex(mesh, c + radius * glm::vec3(std::cos(a), 0.0f, std::sin(a)), n);
        }
        for (int i = 0; i < segments; ++i)
            smoothTriangle(mesh, centre, centre + 1 + static_cast<uint32_t>(i),
                           centre + 1 + static_cast<uint32_t>((i + 1) % segments), n);
    }
}

void addCard(Mesh& mesh, glm::vec3 base, glm::vec3 halfWidth, glm::vec3 up, float tipScale) {
    if (tipScale <= 0.0f)
        addTriangle(mesh, base - halfWidth, base + halfWidth, base + up);
    else
        addQuad(mesh, base - halfWidth, base + halfWidth, base + up + tipScale * halfWidth,
                base + up - tipScale * halfWidth);
}

Material matte(std::string name, glm::vec3 albedo) {
    return Material{.name = std::move(name), .albedo = albedo, .specular = glm::vec3(0.0f), .roughness = 1.0f};
}

Material dielectric(std::string name, glm::vec3 albedo, float roughness) {
    return Material{.name = std::move(name), .albedo = albedo, .specular = glm::vec3(0.04f), .roughness = roughness};
}

Material metal(std::string name, glm::vec3 f0, float roughness) {
    return Material{.name = std::move(name), .albedo = glm::vec3(0.0f), .specular = f0, .roughness = roughness};
}

Material emitter(std::string name, glm::vec3 radiance) {
    return Material{.name = std::move(name), .albedo = glm::vec3(0.0f), .specular = glm::vec3(0.0f),
                    .roughness = 1.0f, .emission = radiance};
}

uint32_t addMaterial(Scene& scene, Material material) {
    scene.materials.push_back(std::move(material));
    return static_cast<uint32_t>(scene.materials.size() - 1);
}

CameraKey lookToward(float time, glm::vec3 position, glm::vec3 point, float verticalFovDegrees) {
    return CameraKey{.time = time, .position = position, .target = position + glm::normalize(point - position),
                     .up = glm::vec3(0.0f, 1.0f, 0.0f), .verticalFovDegrees = verticalFovDegrees};
}

float sunRadianceFor(float irradiance, float angularRadiusDegrees) {
    // 2 pi (1 - cos r) = 4 pi sin^2(r/2): no cancellation for a sub-degree disc.
    const double half = 0.5 * static_cast<double>(angularRadiusDegrees) * 3.14159265358979323846 / 180.0;
    const double solidAngle = 4.0 * 3.14159265358979323846 * std::sin(half) * std::sin(half);
    return static_cast<float>(static_cast<double>(irradiance) / solidAngle);
}

} // namespace hush::tracer::build
