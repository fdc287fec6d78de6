#pragma once
// The pinhole camera: primary rays for continuous pixel coordinates and the
// projection of world points back to them, with DESIGN.md's conventions (camera
// looks down -Z, pixel (0,0) top-left, centres at +0.5).
#include <cstdint>

#include <glm/glm.hpp>

#include <hush/tracer/frame.hpp>
#include <hush/tracer/scene.hpp>

namespace hush::tracer::detail {

struct CameraModel {
    glm::mat4 view{1.0f}, inverseView{1.0f};
    glm::vec3 position{0.0f};
    float tanHalfFovY = 1.0f, aspect = 1.0f;
    uint32_t width = 1, height = 1;
    glm::vec2 jitter{0.0f};
    CameraInfo info;

    // Unit world-space direction through continuous pixel coordinates (x right, y down).
    glm::vec3 rayDirection(glm::vec2 pixel) const;
    // Continuous pixel coordinates of a world point (without jitter); false when the
    // point is behind the camera.
    bool project(glm::vec3 world, glm::vec2& pixel) const;
    // The pixel offset a direction at infinity moves between two cameras.
    float viewDepth(glm::vec3 world) const { return -(view * glm::vec4(world, 1.0f)).z; }
};

CameraModel makeCamera(const CameraKey& key, uint32_t width, uint32_t height, float nearPlane, float farPlane,
                       glm::vec2 jitter);

// The subpixel jitter of frame `index` (Halton 2,3, centred), in pixels.
glm::vec2 frameJitter(uint32_t index);

} // namespace hush::tracer::detail
