// The motion and camera conventions: motion is the previous-frame pixel position minus
// the current one, in pixels (docs/frame-format.md); the cameras in the header must
// see each position where its pixel is, and predict the motion of static geometry.
#include <cmath>
#include <cstdint>
#include <optional>

#include "frame_check_detail.hpp"

namespace hush::tracer::detail {
namespace {

// The readings of a motion layer an integration could have meant, the right one first.
struct MotionReading {
    const char* name;
    const char* diagnosis;   // what it means when this reading fits better than +motion
    glm::vec2 (*displacement)(glm::vec2 motion, glm::vec2 size);
};

const MotionReading kReadings[] = {
    {"+motion", "", [](glm::vec2 m, glm::vec2) { return m; }},
    {"-motion",
     "the vectors point the wrong way: write previous minus current position (not current minus previous, "
     "not towards the next frame)",
     [](glm::vec2 m, glm::vec2) { return -m; }},
    {"y flipped", "y points up: hush's motion has y down, like its pixel rows",
     [](glm::vec2 m, glm::vec2) { return glm::vec2(m.x, -m.y); }},
    {"x (W/2, H/2)", "the vectors are in NDC units: multiply by (width/2, height/2) for pixels",
     [](glm::vec2 m, glm::vec2 size) { return m * size * 0.5f; }},
    {"x (W, H)", "the vectors are in UV units: multiply by (width, height) for pixels",
     [](glm::vec2 m, glm::vec2 size) { return m * size; }},
};
constexpr size_t kReadingCount = sizeof kReadings / sizeof kReadings[0];
constexpr size_t kMinimumPixels = 16;
constexpr double kLost = 1e6;   // the error of a reading that leaves the image or the surface

// The surface's position in the previous frame at continuous pixel q: bilinear over
// those of the 2x2 texels around q that are on the pixel's own mesh (weights
// renormalised, so thin geometry still counts); false if none is.
bool positionBefore(const Frame& previous, const std::vector<uint8_t>& hitBefore, float meshId, glm::vec2 q,
                    glm::vec3& position) {
    const glm::vec2 corner = q - 0.5f;
    const int x0 = int(std::floor(corner.x)), y0 = int(std::floor(corner.y));
    const glm::vec2 t = corner - glm::vec2(float(x0), float(y0));
    const bool hasIds = previous.has(Channel::MeshId);
    glm::vec3 sum(0.0f);
    float weights = 0.0f;
    for (int dy = 0; dy <= 1; ++dy) {
        for (int dx = 0; dx <= 1; ++dx) {
            const int px = x0 + dx, py = y0 + dy;
            if (px < 0 || py < 0 || px >= int(previous.width) || py >= int(previous.height)) continue;
            if (!hitBefore[size_t(py) * previous.width + size_t(px)]) continue;
            if (hasIds && *previous.get(Channel::MeshId).at(uint32_t(px), uint32_t(py)) != meshId) continue;
            const float w = (dx ? t.x : 1.0f - t.x) * (dy ? t.y : 1.0f - t.y) + 1e-6f;
            sum += w * texel3(previous.get(Channel::Position), uint32_t(px), uint32_t(py));
            weights += w;
        }
    }
    if (weights <= 0.0f) return false;
    position = sum / weights;
    return true;
}

// How far one pixel spans on the surface: turns a position error into pixels.
float footprint(const Frame& frame, uint32_t x, uint32_t y) {
    const Image& p = frame.get(Channel::Position);
    const uint32_t nx = x + 1 < frame.width ? x + 1 : x - 1, ny = y + 1 < frame.height ? y + 1 : y - 1;
    return glm::min(glm::length(texel3(p, nx, y) - texel3(p, x, y)), glm::length(texel3(p, x, ny) - texel3(p, x, y)));
}

// For each reading, the distance in pixels between a pixel's surface point and the
// previous frame's at the reprojected position: near zero for the right reading on
// static geometry, about the reading's own error elsewhere.
void measurePair(const Frame& current, const Frame& previous, std::vector<double> (&errors)[kReadingCount]) {
    const std::vector<uint8_t> hitNow = hitMask(current), hitBefore = hitMask(previous);
    const glm::vec2 size(float(current.width), float(current.height));
    const Image& motion = current.get(Channel::Motion);
    for (uint32_t y = 0; y < current.height; ++y) {
        for (uint32_t x = 0; x < current.width; ++x) {
            if (!hitNow[size_t(y) * current.width + x]) continue;
            const glm::vec2 m(motion.at(x, y)[0], motion.at(x, y)[1]);
            const float pixelSize = footprint(current, x, y);
            if (!std::isfinite(m.x) || !std::isfinite(m.y) || !(pixelSize > 0.0f) || !std::isfinite(pixelSize)) continue;
            float spread = 0.0f;   // pixels where every reading lands alike tell nothing
            for (const MotionReading& r : kReadings) spread = glm::max(spread, glm::length(r.displacement(m, size) - m));
            if (spread < 0.1f) continue;
            const glm::vec3 now = texel3(current.get(Channel::Position), x, y);
            const float id = current.has(Channel::MeshId) ? *current.get(Channel::MeshId).at(x, y) : 0.0f;
            for (size_t k = 0; k < kReadingCount; ++k) {
                const glm::vec2 q = glm::vec2(float(x) + 0.5f, float(y) + 0.5f) + kReadings[k].displacement(m, size);
                glm::vec3 before;
                errors[k].push_back(positionBefore(previous, hitBefore, id, q, before)
                                        ? double(glm::length(before - now) / pixelSize) : kLost);
            }
        }
    }
}

std::string pixels(double error) {
    return error >= kLost ? std::string("lost") : number(error, 2) + " px";
}

} // namespace

ConventionCheck checkMotion(std::span<const Frame> frames) {
    std::string missing;
    if (lacks(frames, {Channel::Motion, Channel::Position}, missing)) return skipped("motion", missing);
    if (frames.size() < 2) return skipped("motion", "one frame: the sign needs two consecutive frames");
    std::vector<double> errors[kReadingCount];
    for (size_t i = 1; i < frames.size(); ++i) measurePair(frames[i], frames[i - 1], errors);
    if (errors[0].size() < kMinimumPixels)
        return skipped("motion", "fewer than " + std::to_string(kMinimumPixels) +
                                     " pixels move: render frames where the camera or objects move");
    double median_[kReadingCount];
    size_t best = 0;
    std::string evidence = "reprojected into the frame before (frames " + std::to_string(frames.front().index) + "-" +
                           std::to_string(frames.back().index) + ", " + std::to_string(errors[0].size()) +
                           " moving pixels), the surface lands off its position by (median) ";
    for (size_t k = 0; k < kReadingCount; ++k) {
        median_[k] = median(errors[k]);
        if (median_[k] < median_[best]) best = k;
        evidence += std::string(k ? ", " : "") + kReadings[k].name + " " + pixels(median_[k]);
    }
    if (best != 0 && median_[best] < 0.5 * median_[0] - 0.05)
        return failed("motion", evidence + ": " + kReadings[best].diagnosis);
    if (median_[0] > 0.5)
        return failed("motion", evidence + ": no reading matches the previous frame (are the frames consecutive?)");
    return passed("motion", evidence + ": sign, direction and units OK");
}

namespace {

struct CameraErrors {
    std::vector<double> ownPixel, transposed, yUp, motion;
};

CameraInfo transposedCamera(const CameraInfo& camera) {
    CameraInfo t = camera;
    t.view = glm::transpose(camera.view);
    t.projection = glm::transpose(camera.projection);
    return t;
}

// Every 2nd pixel in each direction is plenty for a median.
void measureCamera(const Frame& frame, CameraErrors& errors) {
    const std::vector<uint8_t> hit = hitMask(frame);
    const Image& position = frame.get(Channel::Position);
    const CameraInfo transposed = transposedCamera(frame.camera);
    const bool hasMotion = frame.has(Channel::Motion);
    for (uint32_t y = 0; y < frame.height; y += 2) {
        for (uint32_t x = 0; x < frame.width; x += 2) {
            if (!hit[size_t(y) * frame.width + x]) continue;
            const glm::vec3 p = texel3(position, x, y);
            const glm::vec2 centre = glm::vec2(float(x) + 0.5f, float(y) + 0.5f) + frame.camera.jitter;
            glm::vec2 now, alt, before;
            if (!projectToPixel(frame.camera, p, frame.width, frame.height, now)) {
                errors.ownPixel.push_back(1e9);
                continue;
            }
            errors.ownPixel.push_back(glm::length(now - centre));
            errors.yUp.push_back(glm::length(glm::vec2(now.x, float(frame.height) - now.y) - centre));
            errors.transposed.push_back(projectToPixel(transposed, p, frame.width, frame.height, alt)
                                            ? glm::length(alt - centre) : 1e9);
            if (hasMotion && projectToPixel(frame.previousCamera, p, frame.width, frame.height, before)) {
                const glm::vec2 m(frame.get(Channel::Motion).at(x, y)[0], frame.get(Channel::Motion).at(x, y)[1]);
                errors.motion.push_back(glm::length(m - (before - now)));
            }
        }
    }
}

} // namespace

ConventionCheck checkCamera(std::span<const Frame> frames) {
    std::string missing;
    if (lacks(frames, {Channel::Position}, missing)) return skipped("camera", missing + " to compare the camera with");
    for (const Frame& frame : frames)
        if (!hasCamera(frame.camera))
            return skipped("camera", "frame " + std::to_string(frame.index) +
                                         " has no hush.camera.* attributes: nothing to check, and chains that use the "
                                         "camera (mara's glossy reprojection, rdae's view-space normals) see an identity one");
    CameraErrors errors;
    for (const Frame& frame : frames) measureCamera(frame, errors);
    const double own = median(errors.ownPixel);
    std::string evidence = "positions project through hush.camera.view and .projection to their own pixel centre "
                           "(+ jitter) within " + (own >= 1e9 ? std::string("nothing: most lie behind it") : number(own) + " px (median)");
    if (own > 0.5) {
        const double transposed = median(errors.transposed), yUp = median(errors.yUp);
        std::string hint = "check the matrices' conventions (docs/frame-format.md: Matrices, Camera model)";
        if (transposed < 0.5) hint = "the matrices are transposed (" + number(transposed) + " px if read the other way)";
        else if (yUp < 0.5) hint = "the projection has y up in NDC (" + number(yUp) + " px flipped); hush's has y down, as Vulkan's";
        return failed("camera", evidence + ": " + hint);
    }
    if (!errors.motion.empty()) {
        const double motion = median(errors.motion);
        evidence += "; motion agrees with the two cameras' prediction for static geometry within " + number(motion) +
                    " px (median)";
        if (motion > 0.5) return failed("camera", evidence + ": motion or hush.previousCamera.* is wrong");
    }
    return passed("camera", evidence);
}

} // namespace hush::tracer::detail
