// The geometric conventions: unit world-space normals, linear view-axis depth, and a
// meshid whose misses agree with the other layers (docs/frame-format.md, Layers).
#include <cmath>
#include <set>

#include "frame_check_detail.hpp"

namespace hush::tracer::detail {
namespace {

// The smaller of the forward and backward differences of position: the one that
// stays on the pixel's own surface at a silhouette.
glm::vec3 positionStep(const Image& position, uint32_t x, uint32_t y, int dx, int dy) {
    const glm::vec3 p = texel3(position, x, y);
    const glm::vec3 forward = texel3(position, x + dx, y + dy) - p;
    const glm::vec3 backward = p - texel3(position, x - dx, y - dy);
    return glm::dot(forward, forward) < glm::dot(backward, backward) ? forward : backward;
}

struct NormalTally {
    uint64_t hits = 0, notUnit = 0, compared = 0, agreeWorld = 0, agreeView = 0;
};

void tallyNormals(const Frame& frame, NormalTally& tally) {
    const std::vector<uint8_t> hit = hitMask(frame);
    const Image& normal = frame.get(Channel::Normal);
    const bool hasPosition = frame.has(Channel::Position);
    // View-space normals mapped to world space, as they would be if that were their space.
    const glm::mat3 viewToWorld = glm::transpose(glm::mat3(frame.camera.view));
    for (uint32_t y = 0; y < frame.height; ++y) {
        for (uint32_t x = 0; x < frame.width; ++x) {
            if (!hit[size_t(y) * frame.width + x]) continue;
            const glm::vec3 n = texel3(normal, x, y);
            ++tally.hits;
            if (!(std::fabs(glm::length(n) - 1.0f) <= 0.02f)) ++tally.notUnit;
            if (!hasPosition || x == 0 || y == 0 || x + 1 >= frame.width || y + 1 >= frame.height) continue;
            const Image& position = frame.get(Channel::Position);
            const glm::vec3 surface =
                glm::cross(positionStep(position, x, y, 1, 0), positionStep(position, x, y, 0, 1));
            const float area = glm::length(surface);
            if (!(area > 0.0f) || !std::isfinite(area) || glm::length(n) < 0.5f) continue;
            ++tally.compared;
            tally.agreeWorld += std::fabs(glm::dot(glm::normalize(n), surface / area)) > 0.98f;
            tally.agreeView += std::fabs(glm::dot(glm::normalize(viewToWorld * n), surface / area)) > 0.98f;
        }
    }
}

bool cameraRotates(std::span<const Frame> frames) {
    for (const Frame& frame : frames)
        if (glm::length(glm::mat3(frame.camera.view)[0] - glm::vec3(1, 0, 0)) > 0.05f ||
            glm::length(glm::mat3(frame.camera.view)[1] - glm::vec3(0, 1, 0)) > 0.05f)
            return true;
    return false;
}

} // namespace

ConventionCheck checkNormal(std::span<const Frame> frames) {
    std::string missing;
    if (lacks(frames, {Channel::Normal}, missing)) return skipped("normal", missing);
    NormalTally tally;
    for (const Frame& frame : frames) tallyNormals(frame, tally);
    if (tally.hits == 0) return skipped("normal", "no pixel hits a surface");
    const double notUnit = double(tally.notUnit) / double(tally.hits);
    std::string evidence = percent(notUnit) + " of the hit pixels' normals are not unit length";
    if (notUnit > 0.01) return failed("normal", evidence + ": normalise them (and write zero only where nothing is hit)");
    if (tally.compared < 64)
        return passed("normal", evidence + "; their space is not checked (no 'position' layer to compare with)");
    const double world = double(tally.agreeWorld) / double(tally.compared);
    const double view = double(tally.agreeView) / double(tally.compared);
    evidence += "; within 11 degrees of the surface the positions describe in " + percent(world) + " of pixels";
    if (!cameraRotates(frames)) return passed("normal", evidence + " (the camera is axis-aligned: view space is not told apart)");
    evidence += " (read as view-space normals: " + percent(view) + ")";
    if (view > world + 0.2) return failed("normal", evidence + ": the normals are in view space; hush's are in world space");
    if (world < 0.3) return failed("normal", evidence + ": the normals do not follow the surfaces");
    return passed("normal", evidence + ": world space OK");
}

namespace {

struct DepthErrors {
    std::vector<double> axial, radial, zBuffer;
};

void measureDepth(const Frame& frame, DepthErrors& errors) {
    const std::vector<uint8_t> hit = hitMask(frame);
    const Image& depth = frame.get(Channel::Depth);
    const Image& position = frame.get(Channel::Position);
    for (uint32_t y = 0; y < frame.height; y += 2) {
        for (uint32_t x = 0; x < frame.width; x += 2) {
            if (!hit[size_t(y) * frame.width + x]) continue;
            const glm::vec3 p = texel3(position, x, y);
            const double d = *depth.at(x, y);
            const glm::vec4 view = frame.camera.view * glm::vec4(p, 1.0f);
            const glm::vec4 clip = frame.camera.projection * view;
            const double axial = -view.z;
            if (!(axial > 0.0)) continue;
            errors.axial.push_back(std::fabs(d - axial) / axial);
            errors.radial.push_back(std::fabs(d - glm::length(glm::vec3(view))) / axial);
            errors.zBuffer.push_back(clip.w > 0.0f ? std::fabs(d - clip.z / clip.w) / axial : 1e9);
        }
    }
}

} // namespace

ConventionCheck checkDepth(std::span<const Frame> frames) {
    std::string missing;
    if (lacks(frames, {Channel::Depth}, missing)) return skipped("depth", missing);
    if (lacks(frames, {Channel::Position}, missing) || !hasCamera(frames[0].camera))
        return skipped("depth", (missing.empty() ? std::string("no hush.camera.* attributes") : missing) +
                                    ": nothing to compare the depth with");
    DepthErrors errors;
    for (const Frame& frame : frames) measureDepth(frame, errors);
    if (errors.axial.empty()) return skipped("depth", "no pixel hits a surface in front of the camera");
    const double axial = median(errors.axial), radial = median(errors.radial), zBuffer = median(errors.zBuffer);
    const std::string evidence = "depth differs from the view-axis distance of 'position' by " + percent(axial) +
                                 " (median; from the distance to the camera: " + percent(radial) +
                                 ", from a z-buffer value: " + percent(zBuffer) + ")";
    if (axial <= 0.005) return passed("depth", evidence + ": linear view-axis depth OK");
    if (zBuffer < 0.5 * axial) return failed("depth", evidence + ": depth is a z-buffer (NDC) value; hush's is linear, -z in view space");
    if (radial < 0.5 * axial) return failed("depth", evidence + ": depth is the distance to the camera; hush's is along the view axis");
    return failed("depth", evidence + ": depth does not match the positions and the camera");
}

ConventionCheck checkMeshId(std::span<const Frame> frames) {
    std::string missing;
    if (lacks(frames, {Channel::MeshId}, missing)) return skipped("meshid", missing);
    uint64_t pixels = 0, fractional = 0, disagree = 0, compared = 0;
    std::set<float> ids;
    for (const Frame& frame : frames) {
        const auto& id = frame.get(Channel::MeshId).pixels;
        const bool hasNormal = frame.has(Channel::Normal);
        for (size_t i = 0; i < id.size(); ++i) {
            ++pixels;
            if (id[i] >= 0.0f && id[i] != std::floor(id[i])) ++fractional;
            if (id[i] >= 0.0f && ids.size() < 1000) ids.insert(id[i]);
            if (!hasNormal) continue;
            const float* n = frame.get(Channel::Normal).pixels.data() + 3 * i;
            const bool normalHit = n[0] != 0.0f || n[1] != 0.0f || n[2] != 0.0f;
            ++compared;
            disagree += normalHit != (id[i] >= 0.0f);
        }
    }
    std::string evidence = std::to_string(ids.size()) + (ids.size() >= 1000 ? "+" : "") + " distinct ids";
    if (fractional > 0)
        return failed("meshid", evidence + ", " + percent(double(fractional) / double(pixels)) +
                                    " of them not whole numbers: write the id itself (UINT), not a normalised value");
    if (compared > 0) {
        const double rate = double(disagree) / double(compared);
        evidence += "; meshid and normal disagree on whether a surface was hit in " + percent(rate) + " of pixels";
        if (rate > 0.01)
            return failed("meshid", evidence + ": write 0xFFFFFFFF only where nothing is hit (a normalised id turns "
                                               "ids into 0 and 0xFFFFFFFF)");
    }
    return passed("meshid", evidence + ": OK");
}

} // namespace hush::tracer::detail
