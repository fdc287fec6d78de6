#include "camera_model.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "sampling.hpp"

namespace hush::tracer::detail {

CameraModel makeCamera(const CameraKey& key, uint32_t width, uint32_t height, float nearPlane, float farPlane,
                       glm::vec2 jitter) {
    CameraModel c;
    c.width = width;
    c.height = height;
    c.aspect = float(width) / float(height);
    c.tanHalfFovY = std::tan(glm::radians(key.verticalFovDegrees) * 0.5f);
    c.position = key.position;
    c.view = glm::lookAtRH(key.position, key.target, key.up);
    c.inverseView = glm::inverse(c.view);
    c.jitter = jitter;
    c.info.view = c.view;
    // Vulkan clip space: depth 0..1 and y pointing down in NDC, as hush's shaders see it.
    c.info.projection = glm::perspectiveRH_ZO(glm::radians(key.verticalFovDegrees), c.aspect, nearPlane, farPlane);
    c.info.projection[1][1] *= -1.0f;
    c.info.jitter = jitter;
    c.info.position = key.position;
    c.info.verticalFovDegrees = key.verticalFovDegrees;
    c.info.nearPlane = nearPlane;
    c.info.farPlane = farPlane;
    return c;
}

glm::vec3 CameraModel::rayDirection(glm::vec2 pixel) const {
    const float ndcX = 2.0f * pixel.x / float(width) - 1.0f;
    const float ndcY = 1.0f - 2.0f * pixel.y / float(height);
    const glm::vec3 viewDir(ndcX * tanHalfFovY * aspect, ndcY * tanHalfFovY, -1.0f);
    return glm::normalize(glm::vec3(inverseView * glm::vec4(viewDir, 0.0f)));
}

bool CameraModel::project(glm::vec3 world, glm::vec2& pixel) const {
    const glm::vec3 v = glm::vec3(view * glm::vec4(world, 1.0f));
    if (v.z >= -1e-8f) return false;
    const float ndcX = v.x / (-v.z * tanHalfFovY * aspect);
    const float ndcY = v.y / (-v.z * tanHalfFovY);
    pixel = {(ndcX + 1.0f) * 0.5f * float(width), (1.0f - ndcY) * 0.5f * float(height)};
    return true;
}

glm::vec2 frameJitter(uint32_t index) {
    return {radicalInverse(2, index + 1) - 0.5f, radicalInverse(3, index + 1) - 0.5f};
}

} // namespace hush::tracer::detail
