#include "reference/common_surface.hpp"

#include <cmath>

namespace hush::passes_test::reference {

namespace {
float slope(const FloatImage& depth, const FloatImage& mesh, int x, int y, int ax, int ay) {
    const float z = depth.at(uint32_t(x), uint32_t(y));
    const float id = mesh.at(uint32_t(x), uint32_t(y));
    const int lx = x - ax, ly = y - ay, hx = x + ax, hy = y + ay;
    const bool hasLo = lx >= 0 && ly >= 0 && mesh.at(uint32_t(lx), uint32_t(ly)) == id;
    const bool hasHi = hx < int(depth.width) && hy < int(depth.height) && mesh.at(uint32_t(hx), uint32_t(hy)) == id;
    const float dLo = hasLo ? z - depth.at(uint32_t(lx), uint32_t(ly)) : 0.0f;
    const float dHi = hasHi ? depth.at(uint32_t(hx), uint32_t(hy)) - z : 0.0f;
    if (hasLo && hasHi) return std::fabs(dLo) < std::fabs(dHi) ? dLo : dHi;
    return hasLo ? dLo : dHi;
}
} // namespace

SurfaceImages surface(const FloatImage& normal, const FloatImage& depth, const FloatImage& meshId) {
    SurfaceImages s{FloatImage(depth.width, depth.height, 4), FloatImage(depth.width, depth.height, 4)};
    for (uint32_t y = 0; y < depth.height; ++y)
        for (uint32_t x = 0; x < depth.width; ++x) {
            const float nx = normal.at(x, y, 0), ny = normal.at(x, y, 1), nz = normal.at(x, y, 2);
            const float len = std::sqrt(nx * nx + ny * ny + nz * nz);
            const float inv = len > 1e-6f && meshId.at(x, y) >= 0.0f ? 1.0f / len : 0.0f;   // no surface: normal 0
            s.normalDepth.at(x, y, 0) = nx * inv;
            s.normalDepth.at(x, y, 1) = ny * inv;
            s.normalDepth.at(x, y, 2) = nz * inv;
            s.normalDepth.at(x, y, 3) = depth.at(x, y);
            s.gradientMesh.at(x, y, 0) = slope(depth, meshId, int(x), int(y), 1, 0);
            s.gradientMesh.at(x, y, 1) = slope(depth, meshId, int(x), int(y), 0, 1);
            s.gradientMesh.at(x, y, 2) = meshId.at(x, y);
        }
    return s;
}

} // namespace hush::passes_test::reference
