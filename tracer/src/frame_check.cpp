// checkFrameConventions: runs each convention's check (frame_check_*.cpp) and the
// helpers they share.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <hush/core/error.hpp>

#include "frame_check_detail.hpp"

namespace hush::tracer {

const char* verdictName(CheckVerdict verdict) {
    switch (verdict) {
    case CheckVerdict::Pass: return "pass";
    case CheckVerdict::Fail: return "FAIL";
    case CheckVerdict::Skipped: return "skip";
    }
    return "?";
}

std::vector<ConventionCheck> checkFrameConventions(std::span<const Frame> frames) {
    if (frames.empty()) throw Error(ErrorKind::InvalidArgument, "checkFrameConventions: no frames to check");
    for (const Frame& frame : frames) {
        if (frame.width != frames[0].width || frame.height != frames[0].height)
            throw Error(ErrorKind::InvalidArgument,
                        "checkFrameConventions: frame " + std::to_string(frame.index) + " is " +
                            std::to_string(frame.width) + "x" + std::to_string(frame.height) + ", frame " +
                            std::to_string(frames[0].index) + " " + std::to_string(frames[0].width) + "x" +
                            std::to_string(frames[0].height) + ": a sequence keeps one size");
    }
    const ConventionCheck camera = detail::checkCamera(frames);
    // Depth is measured through the camera: a wrong camera is one finding, not two.
    ConventionCheck depth = camera.verdict == CheckVerdict::Fail
                                ? detail::skipped("depth", "measured through the camera, which failed its own check")
                                : detail::checkDepth(frames);
    return {detail::checkMotion(frames), camera, detail::checkNormal(frames), std::move(depth),
            detail::checkMeshId(frames), detail::checkAlbedo(frames), detail::checkRadiance(frames)};
}

namespace detail {

std::vector<uint8_t> hitMask(const Frame& frame) {
    const size_t count = size_t(frame.width) * frame.height;
    std::vector<uint8_t> hit(count, 1);
    if (frame.has(Channel::MeshId)) {
        const auto& ids = frame.get(Channel::MeshId).pixels;
        for (size_t i = 0; i < count; ++i) hit[i] = ids[i] >= 0.0f;
    } else if (frame.has(Channel::Normal)) {
        const auto& n = frame.get(Channel::Normal).pixels;
        for (size_t i = 0; i < count; ++i) hit[i] = n[3 * i] != 0.0f || n[3 * i + 1] != 0.0f || n[3 * i + 2] != 0.0f;
    } else if (frame.has(Channel::Depth)) {
        const auto& d = frame.get(Channel::Depth).pixels;
        for (size_t i = 0; i < count; ++i) hit[i] = d[i] < frame.camera.farPlane * 0.999f;
    }
    return hit;
}

bool hasCamera(const CameraInfo& camera) {
    return camera.view != glm::mat4(1.0f) || camera.projection != glm::mat4(1.0f);
}

bool projectToPixel(const CameraInfo& camera, glm::vec3 world, uint32_t width, uint32_t height, glm::vec2& pixel) {
    const glm::vec4 clip = camera.projection * camera.view * glm::vec4(world, 1.0f);
    if (!(clip.w > 1e-8f)) return false;
    pixel = {(clip.x / clip.w + 1.0f) * 0.5f * float(width), (clip.y / clip.w + 1.0f) * 0.5f * float(height)};
    return std::isfinite(pixel.x) && std::isfinite(pixel.y);
}

glm::vec3 texel3(const Image& image, uint32_t x, uint32_t y) {
    const float* p = image.at(x, y);
    return {p[0], p[1], p[2]};
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

std::string number(double value, int digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return text;
}

std::string percent(double fraction) {
    return number(100.0 * fraction, fraction < 0.1 ? 2 : 3) + " %";
}

ConventionCheck passed(std::string convention, std::string evidence) {
    return {std::move(convention), CheckVerdict::Pass, std::move(evidence)};
}

ConventionCheck failed(std::string convention, std::string evidence) {
    return {std::move(convention), CheckVerdict::Fail, std::move(evidence)};
}

ConventionCheck skipped(std::string convention, std::string why) {
    return {std::move(convention), CheckVerdict::Skipped, std::move(why)};
}

bool lacks(std::span<const Frame> frames, std::initializer_list<Channel> channels, std::string& missing) {
    for (Channel channel : channels) {
        for (const Frame& frame : frames) {
            if (frame.has(channel)) continue;
            missing = "no '" + std::string(channelInfo(channel).name) + "' layer";
            return true;
        }
    }
    return false;
}

} // namespace detail
} // namespace hush::tracer
