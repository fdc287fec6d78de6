// The renderer's outputs: convergence of the 1-spp estimate to the reference,
// motion vectors, G-buffer invariants and determinism.
#include <cmath>
#include <cstring>

#include <catch2/catch.hpp>

#include <hush/tracer/builtin_scenes.hpp>
#include <hush/tracer/renderer.hpp>

#include "tracer_test_scenes.hpp"

using namespace hush::tracer;

namespace {

double rmse(const std::vector<double>& a, const std::vector<float>& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(sum / double(a.size()));
}

// Continuous pixel coordinates of a world point through a frame's stored matrices:
// an independent path from the tracer's own camera code.
glm::vec2 projectWithMatrices(const CameraInfo& c, glm::vec3 p, uint32_t w, uint32_t h) {
    const glm::vec4 clip = c.projection * c.view * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x + 1.0f) * 0.5f * float(w), (ndc.y + 1.0f) * 0.5f * float(h)};
}

} // namespace

TEST_CASE("renderer: the mean of k 1-spp frames approaches the reference like 1/sqrt(k)", "[tracer][convergence]") {
    const Renderer renderer(test::tabletop(false));
    RenderSettings settings;
    settings.width = 32;
    settings.height = 24;
    settings.channels = {Channel::Color, Channel::Reference};
    settings.referenceSpp = 4096;
    const Frame first = renderer.render(0, settings);
    const Image& reference = first.get(Channel::Reference);

    settings.channels = {Channel::Color};
    std::vector<double> sum(reference.pixels.size(), 0.0);
    std::vector<double> errors;
    uint32_t frames = 0;
    for (uint32_t k : {4u, 16u, 64u, 256u}) {
        for (; frames < k; ++frames) {
            const Frame frame = renderer.render(frames, settings);   // keep it: get() returns a reference into it
            const Image& c = frame.get(Channel::Color);
            for (size_t i = 0; i < sum.size(); ++i) sum[i] += c.pixels[i];
        }
        std::vector<double> mean(sum.size());
        for (size_t i = 0; i < sum.size(); ++i) mean[i] = sum[i] / k;
        errors.push_back(rmse(mean, reference.pixels));
    }
    for (size_t i = 1; i < errors.size(); ++i) {
        const double ratio = errors[i - 1] / errors[i];
        INFO("RMSE " << errors[i - 1] << " -> " << errors[i] << " for 4x the frames: ratio " << ratio << " (ideal 2)");
        // 4x the samples halves the error. Quasi-random samples may do better than
        // 2; the reference's own noise (4096 spp) caps the last step a little.
        REQUIRE(ratio > 1.6);
        REQUIRE(ratio < 4.0);
    }
}

TEST_CASE("renderer: motion vectors reproject static geometry onto the previous frame", "[tracer][motion]") {
    const Renderer renderer(test::tabletop(true));
    RenderSettings settings;
    settings.width = 64;
    settings.height = 48;
    settings.channels = {Channel::Position, Channel::Motion, Channel::MeshId};
    // Several frames apart, so the camera moves by pixels, not fractions of one; the
    // previous-camera record is checked on the adjacent frame below.
    const Frame before = renderer.render(9, settings);
    Frame now = renderer.render(10, settings);
    REQUIRE(now.previousCamera.view == before.camera.view);
    now = renderer.render(16, settings);
    const Frame sixBefore = renderer.render(15, settings);
    REQUIRE(now.previousCamera.view == sixBefore.camera.view);

    REQUIRE(now.previousCamera.projection == sixBefore.camera.projection);

    const Image& pos = now.get(Channel::Position);
    const Image& motion = now.get(Channel::Motion);
    const Image& mesh = now.get(Channel::MeshId);
    double worst = 0.0, moved = 0.0;
    for (uint32_t y = 0; y < now.height; ++y)
        for (uint32_t x = 0; x < now.width; ++x) {
            if (mesh.at(x, y)[0] == kNoMesh) continue;
            const glm::vec3 p(pos.at(x, y)[0], pos.at(x, y)[1], pos.at(x, y)[2]);
            const glm::vec2 expected = projectWithMatrices(sixBefore.camera, p, now.width, now.height);
            const glm::vec2 reprojected(float(x) + 0.5f + motion.at(x, y)[0], float(y) + 0.5f + motion.at(x, y)[1]);
            worst = std::max(worst, double(glm::length(expected - reprojected)));
            moved = std::max(moved, double(glm::length(glm::vec2(motion.at(x, y)[0], motion.at(x, y)[1]))));
        }
    INFO("worst reprojection error " << worst << " px; largest motion " << moved << " px");
    REQUIRE(moved > 0.5);      // the camera did move
    REQUIRE(worst < 0.01);     // and the motion lands where the stored cameras say
}

TEST_CASE("renderer: G-buffer invariants", "[tracer][gbuffer]") {
    const Renderer renderer(test::tabletop(false));
    RenderSettings settings;
    settings.width = 40;
    settings.height = 30;
    settings.channels = {Channel::Normal, Channel::Depth, Channel::MeshId, Channel::Albedo, Channel::Roughness,
                         Channel::Position};
    const Frame a = renderer.render(0, settings);
    const Frame b = renderer.render(5, settings);
    size_t hits = 0;
    for (uint32_t y = 0; y < a.height; ++y)
        for (uint32_t x = 0; x < a.width; ++x) {
            const float id = a.get(Channel::MeshId).at(x, y)[0];
            REQUIRE(id == b.get(Channel::MeshId).at(x, y)[0]);   // still camera: same surfaces
            REQUIRE(a.get(Channel::Depth).at(x, y)[0] > 0.0f);
            if (id == kNoMesh) continue;
            ++hits;
            const float* n = a.get(Channel::Normal).at(x, y);
            REQUIRE(std::abs(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1.0f) < 1e-4f);
            REQUIRE(id == std::floor(id));
            REQUIRE(id < 5.0f);
        }
    REQUIRE(hits > a.width * a.height / 2);
}

TEST_CASE("renderer: the same seed gives the same bits, whatever the thread count", "[tracer][determinism]") {
    const Renderer renderer(test::tabletop(true));
    RenderSettings settings;
    settings.width = 37;
    settings.height = 21;
    settings.channels = {Channel::Color, Channel::Matte, Channel::Glossy, Channel::Reference};
    settings.referenceSpp = 8;
    settings.threads = 1;
    const Frame one = renderer.render(3, settings);
    settings.threads = 3;
    const Frame three = renderer.render(3, settings);
    for (Channel c : settings.channels) {
        const auto& p = one.get(c).pixels;
        const auto& q = three.get(c).pixels;
        REQUIRE(std::memcmp(p.data(), q.data(), p.size() * sizeof(float)) == 0);
    }
    settings.seed = 2;
    const Frame other = renderer.render(3, settings);
    REQUIRE(std::memcmp(other.get(Channel::Color).pixels.data(), one.get(Channel::Color).pixels.data(),
                        one.get(Channel::Color).pixels.size() * sizeof(float)) != 0);
}

TEST_CASE("renderer: only the channels asked for are made", "[tracer][channels]") {
    const Renderer renderer(test::tabletop(false));
    RenderSettings settings;
    settings.width = 8;
    settings.height = 8;
    settings.channels = {Channel::Albedo, Channel::Depth};
    const Frame f = renderer.render(0, settings);
    REQUIRE(f.channels.size() == 2);
    REQUIRE(f.has(Channel::Albedo));
    REQUIRE(!f.has(Channel::Color));
    REQUIRE_THROWS_WITH(f.get(Channel::Color), Catch::Contains("no channel 'color'"));
    settings.channels.clear();
    REQUIRE_THROWS_WITH(renderer.render(0, settings), Catch::Contains("no channels"));
}

TEST_CASE("renderer: in Mara mode direct + indirect still estimates the colour", "[tracer][mara]") {
    // Mara's direct term samples lights only; the sky through the primary bounce
    // must then reach `indirect`, or a chain that adds the two (SVGF) loses it.
    const Renderer renderer(test::tabletop(false));
    RenderSettings settings;
    settings.width = 24;
    settings.height = 16;
    settings.channels = {Channel::Color, Channel::Direct, Channel::Indirect, Channel::Matte};
    double color = 0.0, split = 0.0, pathIndirect = 0.0;
    for (uint32_t f = 0; f < 24; ++f) {
        const Frame frame = renderer.render(f, settings);
        const auto& c = frame.get(Channel::Color).pixels;
        const auto& d = frame.get(Channel::Direct).pixels;
        const auto& i = frame.get(Channel::Indirect).pixels;
        for (size_t k = 0; k < c.size(); ++k) {
            color += c[k];
            split += double(d[k]) + i[k];
        }
    }
    settings.channels = {Channel::Indirect};   // path mode: the sky bounce counts as direct there
    for (uint32_t f = 0; f < 24; ++f) {
        const Frame frame = renderer.render(f, settings);   // keep it: get() returns a reference into it
        for (const float v : frame.get(Channel::Indirect).pixels) pathIndirect += v;
    }
    INFO("mean colour " << color << ", direct + indirect " << split << ", path-mode indirect " << pathIndirect);
    REQUIRE(std::abs(split - color) < 0.03 * color);
}

TEST_CASE("renderer: an anti-aliased reference integrates each pixel's area and changes nothing else",
          "[tracer][reference]") {
    const Renderer renderer(test::tabletop(true));
    RenderSettings settings;
    settings.width = 40;
    settings.height = 24;
    settings.channels = {Channel::Color, Channel::Albedo, Channel::Depth, Channel::Reference};
    settings.referenceSpp = 256;
    const Frame centre = renderer.render(2, settings);
    settings.antialiasedReference = true;
    const Frame area = renderer.render(2, settings);
    // The noisy estimate and the G-buffer still follow the pixel centres, bit for bit.
    for (Channel c : {Channel::Color, Channel::Albedo, Channel::Depth})
        REQUIRE(std::memcmp(centre.get(c).pixels.data(), area.get(c).pixels.data(),
                            centre.get(c).pixels.size() * sizeof(float)) == 0);
    // Both references estimate the same image on average, but not the same pixels:
    // across an edge the area sample mixes both sides.
    const auto& a = area.get(Channel::Reference).pixels;
    const auto& c = centre.get(Channel::Reference).pixels;
    double sumA = 0.0, sumC = 0.0, largest = 0.0, peak = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        sumA += a[i], sumC += c[i];
        largest = std::max(largest, double(std::fabs(a[i] - c[i])));
        peak = std::max(peak, double(c[i]));
    }
    INFO("mean area " << sumA / a.size() << ", mean centre " << sumC / c.size() << ", largest difference " << largest);
    CHECK(std::fabs(sumA - sumC) < 0.05 * sumC);
    CHECK(largest > 0.1 * peak);
}

TEST_CASE("the renderer counts the rays it casts, by kind", "[tracer]") {
    const Renderer renderer(makeBuiltinScene("cornell"));
    RenderSettings s;
    s.width = 16, s.height = 16;
    s.channels = {Channel::Albedo};   // the G-buffer needs the primary rays only
    renderer.render(0, s);
    const RayCounts primaryOnly = renderer.raysCast();
    CHECK(primaryOnly.closestHit == 256);
    CHECK(primaryOnly.occlusion == 0);
    s.channels = {Channel::Color};   // one bounce: per pixel at most 2 more closest hits and 2 shadow rays
    renderer.render(0, s);
    const RayCounts path = renderer.raysCast();
    const uint64_t closest = path.closestHit - primaryOnly.closestHit, shadow = path.occlusion;
    CHECK(closest > 256);
    CHECK(closest <= 3 * 256);
    CHECK(shadow > 0);
    CHECK(shadow <= 2 * 256);
    CHECK(renderer.raysTraced() == path.closestHit + path.occlusion);
}

TEST_CASE("rendering into a reused frame gives the same frame as a fresh one", "[tracer]") {
    const Renderer renderer(makeBuiltinScene("room"));
    RenderSettings s;
    s.width = 24, s.height = 16;
    s.channels = {Channel::Color, Channel::Albedo, Channel::Depth, Channel::Reference};
    s.referenceSpp = 2;
    Frame reused;
    renderer.renderInto(reused, 3, s);   // values everywhere, some of which frame 5 must clear
    s.channels = {Channel::Color, Channel::Albedo, Channel::MeshId};
    s.width = 24;
    renderer.renderInto(reused, 5, s);
    const Frame fresh = renderer.render(5, s);
    CHECK_FALSE(reused.has(Channel::Reference));   // not asked for any more
    CHECK_FALSE(reused.has(Channel::Depth));
    CHECK(reused.referenceSpp == 0);
    CHECK(reused.index == 5);
    for (Channel c : s.channels) {
        INFO("channel " << int(c));
        REQUIRE(reused.has(c));
        CHECK(reused.get(c).pixels == fresh.get(c).pixels);
    }
    s.width = 20;   // another size: the images are replaced
    renderer.renderInto(reused, 5, s);
    CHECK(reused.get(Channel::Albedo).width == 20);
    CHECK(reused.get(Channel::Albedo).pixels == renderer.render(5, s).get(Channel::Albedo).pixels);
}
