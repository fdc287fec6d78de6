// checkFrameConventions (`hush check`): the tracer's own frames pass every check, and
// frames with one convention broken the way integrations break it fail that check,
// with a message that says what is wrong.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <hush/tracer/frame_check.hpp>
#include <hush/tracer/builtin_scenes.hpp>
#include <hush/tracer/renderer.hpp>

using namespace hush::tracer;

namespace {

// Four frames of `room` (a camera that walks and turns), 64x64, every layer the
// checks read.
const std::vector<Frame>& sceneFrames() {
    static const std::vector<Frame> frames = [] {
        Renderer renderer(makeBuiltinScene("room"));
        RenderSettings settings;
        settings.width = settings.height = 64;
        settings.referenceSpp = 0;
        settings.channels = {Channel::Color,    Channel::Direct, Channel::Indirect, Channel::Albedo, Channel::Normal,
                             Channel::Position, Channel::Depth,  Channel::Motion,   Channel::MeshId};
        std::vector<Frame> out;
        for (uint32_t i = 0; i < 4; ++i) out.push_back(renderer.render(i, settings));
        return out;
    }();
    return frames;
}

ConventionCheck find(const std::vector<ConventionCheck>& checks, const std::string& convention) {
    for (const ConventionCheck& check : checks)
        if (check.convention == convention) return check;
    FAIL("no check named " << convention);
    return {};
}

// Breaks every frame with `breakFrame`, then expects `convention` to fail with `words`
// in its message and every other check to keep its verdict.
void expectFailure(const std::string& convention, const std::string& words, const std::function<void(Frame&)>& breakFrame) {
    std::vector<Frame> frames = sceneFrames();
    for (Frame& frame : frames) breakFrame(frame);
    const std::vector<ConventionCheck> checks = checkFrameConventions(frames);
    const ConventionCheck broken = find(checks, convention);
    INFO(broken.evidence);
    CHECK(broken.verdict == CheckVerdict::Fail);
    CHECK(broken.evidence.find(words) != std::string::npos);
}

template <typename F>
void forEachTexel(Frame& frame, Channel channel, F&& change) {
    Image& image = frame.channels.at(channel);
    for (size_t i = 0; i < image.pixels.size(); i += image.channels) change(&image.pixels[i]);
}

float srgbEncode(float linear) {
    const float c = std::fmin(std::fmax(linear, 0.0f), 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

} // namespace

TEST_CASE("frame check: the tracer's own frames pass every convention", "[frame_check]") {
    const std::vector<ConventionCheck> checks = checkFrameConventions(sceneFrames());
    REQUIRE(checks.size() == 7);
    for (const ConventionCheck& check : checks) {
        INFO(check.convention << ": " << check.evidence);
        CHECK(check.verdict == CheckVerdict::Pass);
    }
}

TEST_CASE("frame check: layers a check needs are named when missing", "[frame_check]") {
    std::vector<Frame> frames = sceneFrames();
    for (Frame& frame : frames) frame.channels.erase(Channel::Motion);
    const ConventionCheck motion = find(checkFrameConventions(frames), "motion");
    CHECK(motion.verdict == CheckVerdict::Skipped);
    CHECK(motion.evidence.find("'motion'") != std::string::npos);
    const ConventionCheck single = find(checkFrameConventions(std::span(sceneFrames()).first(1)), "motion");
    CHECK(single.verdict == CheckVerdict::Skipped);
}

TEST_CASE("frame check: motion with the wrong sign or y up or in NDC units fails", "[frame_check]") {
    expectFailure("motion", "wrong way", [](Frame& f) { forEachTexel(f, Channel::Motion, [](float* m) { m[0] = -m[0], m[1] = -m[1]; }); });
    expectFailure("motion", "y points up", [](Frame& f) { forEachTexel(f, Channel::Motion, [](float* m) { m[1] = -m[1]; }); });
    expectFailure("motion", "NDC", [](Frame& f) {
        const float w = float(f.width), h = float(f.height);
        forEachTexel(f, Channel::Motion, [&](float* m) { m[0] /= w * 0.5f, m[1] /= h * 0.5f; });
    });
}

TEST_CASE("frame check: normals in view space fail", "[frame_check]") {
    expectFailure("normal", "view space", [](Frame& f) {
        const glm::mat3 rotation(f.camera.view);
        forEachTexel(f, Channel::Normal, [&](float* n) {
            const glm::vec3 v = rotation * glm::vec3(n[0], n[1], n[2]);
            n[0] = v.x, n[1] = v.y, n[2] = v.z;
        });
    });
}

TEST_CASE("frame check: a z-buffer depth fails", "[frame_check]") {
    expectFailure("depth", "z-buffer", [](Frame& f) {
        const Image& position = f.get(Channel::Position);
        Image& depth = f.channels.at(Channel::Depth);
        for (size_t i = 0; i < depth.pixels.size(); ++i) {
            const float* p = &position.pixels[3 * i];
            const glm::vec4 clip = f.camera.projection * f.camera.view * glm::vec4(p[0], p[1], p[2], 1.0f);
            depth.pixels[i] = clip.z / clip.w;
        }
    });
}

TEST_CASE("frame check: a normalised meshid fails", "[frame_check]") {
    // A UINT id written as a normalised value reads back as 0 or 0xFFFFFFFF.
    expectFailure("meshid", "0xFFFFFFFF", [](Frame& f) { forEachTexel(f, Channel::MeshId, [](float* id) { *id = *id > 0.0f ? kNoMesh : *id; }); });
}

TEST_CASE("frame check: albedo with lighting in it fails", "[frame_check]") {
    expectFailure("albedo", "light", [](Frame& f) {
        const Image& direct = f.get(Channel::Direct);
        Image& albedo = f.channels.at(Channel::Albedo);
        for (size_t i = 0; i < albedo.pixels.size(); ++i) albedo.pixels[i] *= direct.pixels[i];
    });
}

TEST_CASE("frame check: sRGB-encoded radiance fails", "[frame_check]") {
    expectFailure("radiance", "sRGB", [](Frame& f) {
        for (Channel c : {Channel::Color, Channel::Direct, Channel::Indirect})
            for (float& v : f.channels.at(c).pixels) v = srgbEncode(v);
    });
}

TEST_CASE("frame check: transposed camera matrices fail", "[frame_check]") {
    expectFailure("camera", "transposed", [](Frame& f) {
        f.camera.view = glm::transpose(f.camera.view);
        f.camera.projection = glm::transpose(f.camera.projection);
    });
}
