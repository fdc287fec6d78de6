#pragma once
// What the convention checks (frame_check_*.cpp) share: which pixels hit a surface,
// projecting a world point with a frame's camera, and the verdict's wording.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <hush/tracer/frame.hpp>
#include <hush/tracer/frame_check.hpp>

namespace hush::tracer::detail {

// Pixels whose primary ray hit a surface: from meshid where the frame has it, else
// from a non-zero normal, else from a depth short of the far plane; all pixels if
// the frame has none of these.
std::vector<uint8_t> hitMask(const Frame& frame);

// A camera that is not the reader's default (identity view and projection): the file
// had hush.camera.* attributes.
bool hasCamera(const CameraInfo& camera);

// Continuous pixel coordinates (x right, y down, centres at +0.5) of a world point
// through `camera`'s view and projection, jitter not added; false behind the camera.
bool projectToPixel(const CameraInfo& camera, glm::vec3 world, uint32_t width, uint32_t height, glm::vec2& pixel);

glm::vec3 texel3(const Image& image, uint32_t x, uint32_t y);
double median(std::vector<double> values);   // 0 for none
std::string percent(double fraction);        // "0.42 %"
std::string number(double value, int digits = 3);

ConventionCheck passed(std::string convention, std::string evidence);
ConventionCheck failed(std::string convention, std::string evidence);
ConventionCheck skipped(std::string convention, std::string why);
// Skipped, naming the first of `channels` that some frame lacks; nullopt-like empty
// convention when all are present.
bool lacks(std::span<const Frame> frames, std::initializer_list<Channel> channels, std::string& missing);

ConventionCheck checkMotion(std::span<const Frame> frames);
ConventionCheck checkCamera(std::span<const Frame> frames);
ConventionCheck checkNormal(std::span<const Frame> frames);
ConventionCheck checkDepth(std::span<const Frame> frames);
ConventionCheck checkMeshId(std::span<const Frame> frames);
ConventionCheck checkAlbedo(std::span<const Frame> frames);
ConventionCheck checkRadiance(std::span<const Frame> frames);

} // namespace hush::tracer::detail
