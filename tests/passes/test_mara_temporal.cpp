// Mara et al. 2017's temporal stages (3: matte, 8: glossy) against their CPU reference:
// the confidence's smoothstep over d0..d1 in metres (scaled by metresPerUnit), the
// bilinear history fetch, the 3x3 clamp, and no history on the first frame and
// outside the image.
#include <catch2/catch.hpp>

#include <hush/passes/mara/temporal.hpp>

#include "pass_test_util.hpp"
#include "reference/mara_temporal.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

struct MatteScene {
    FloatImage current, motion, position, history, positionHistory;
};

// Positions on a tilted plane in `unit`s; last frame's differ by 0 .. 0.1 m, so the
// confidence takes every value of its smoothstep; some motion leaves the image.
MatteScene matteScene(uint32_t w, uint32_t h, float unit, uint64_t seed) {
    MatteScene s;
    s.current = randomImage(w, h, 3, 0.0f, 2.0f, seed);
    s.history = randomImage(w, h, 3, 0.0f, 2.0f, seed + 1);
    s.motion = makeImage(w, h, 2, [&](uint32_t x, uint32_t y, uint32_t c) {
        if (x == 0 && c == 0) return -3.0f;   // leaves the image
        return 0.37f * float((x + 2 * y + c) % 5) - 0.8f;
    });
    s.position = makeImage(w, h, 3, [&](uint32_t x, uint32_t y, uint32_t c) {
        return (c == 0 ? 0.01f * float(x) : c == 1 ? 0.013f * float(y) : 1.0f + 0.002f * float(x)) / unit;
    });
    const auto offsets = randomImage(w, h, 3, -0.06f, 0.06f, seed + 2);
    s.positionHistory = s.position;
    for (size_t i = 0; i < s.positionHistory.pixels.size(); ++i) s.positionHistory.pixels[i] += offsets.pixels[i] / unit;
    return s;
}

FloatImage runMatte(const MatteScene& s, const passes::MaraTemporalSettings& settings, float metresPerUnit,
                    bool secondFrame) {
    NodeHarness t({s.current.width, s.current.height});
    auto camera = std::make_shared<passes::FrameCamera>();
    camera->metresPerUnit = metresPerUnit;
    const auto out = passes::addMaraMatteTemporalPass(
        t.ctx, "temporal", t.input("current", s.current), t.input("motion", s.motion, rhi::Format::RG32Float),
        t.input("position", s.position), t.input("history", s.history), t.input("position_history", s.positionHistory),
        camera, settings);
    t.graph.markOutput(out);
    if (secondFrame) {
        t.graph.execute();   // frame 0: no history yet
        t.graph.waitIdle();
    }
    return t.runOnce(out);
}

} // namespace

TEST_CASE("mara temporal (matte) matches the CPU reference, with and without history", "[mara][mara-temporal]") {
    test::ValidationScope scope;
    for (auto [unit, metresPerUnit] : {std::pair{1.0f, 1.0f}, std::pair{0.001f, 0.001f}}) {
        INFO("scene units of " << unit << " m");
        const auto s = matteScene(37, 23, unit, 5);
        reference::MaraTemporalParams p;
        p.metresPerUnit = metresPerUnit;
        const auto gpu = runMatte(s, {}, metresPerUnit, true);
        const auto ref = reference::maraMatteTemporal(s.current, s.motion, s.position, s.history, s.positionHistory, p);
        HUSH_REQUIRE_IMAGES_MATCH(gpu, ref, 2e-5f, 2e-5f);
        // Every confidence value occurs: none, full (h) and between.
        size_t none = 0, full = 0, between = 0;
        for (uint32_t y = 0; y < gpu.height; ++y)
            for (uint32_t x = 0; x < gpu.width; ++x) {
                const float c = gpu.at(x, y, 3);
                none += c == 0.0f;
                full += c == 0.98f;
                between += c > 0.0f && c < 0.98f;
            }
        CHECK(none > 0);
        CHECK(full > 0);
        CHECK(between > 0);
        // Column 0 reprojects outside the image: no history.
        for (uint32_t y = 0; y < gpu.height; ++y) CHECK(gpu.at(0, y, 3) == 0.0f);

        p.historyValid = false;
        const auto first = runMatte(s, {}, metresPerUnit, false);
        HUSH_REQUIRE_IMAGES_MATCH(first, reference::maraMatteTemporal(s.current, s.motion, s.position, s.history,
                                                                       s.positionHistory, p),
                                  0.0f, 0.0f);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("mara temporal: 5 cm trusts fully, 7 cm not at all, and history is clamped to the neighbourhood",
          "[mara][mara-temporal]") {
    test::ValidationScope scope;
    const uint32_t w = 5, h = 5;
    MatteScene s;
    s.current = FloatImage(w, h, 3, 1.0f);
    s.history = FloatImage(w, h, 3, 3.0f);   // clamped to the neighbourhood: 1
    s.motion = FloatImage(w, h, 2, 0.0f);
    s.position = FloatImage(w, h, 3, 0.0f);
    s.positionHistory = makeImage(w, h, 3, [](uint32_t x, uint32_t, uint32_t c) {
        return c == 0 ? (x < 2 ? 0.049f : x < 4 ? 0.06f : 0.071f) : 0.0f;
    });
    const auto out = runMatte(s, {}, 1.0f, true);
    CHECK(out.at(0, 2, 3) == Approx(0.98f));
    CHECK(out.at(2, 2, 3) == Approx(0.98f * 0.5f).margin(1e-5));   // the smoothstep's midpoint
    CHECK(out.at(4, 2, 3) == 0.0f);
    for (uint32_t x = 0; x < w; ++x) CHECK(out.at(x, 2, 0) == Approx(1.0f));   // history clamped to 1
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("mara temporal (glossy) reprojects the virtual position with last frame's camera like the reference",
          "[mara][mara-temporal]") {
    test::ValidationScope scope;
    const uint32_t w = 33, h = 21;
    const auto current = randomImage(w, h, 3, 0.0f, 1.0f, 11);
    const auto history = randomImage(w, h, 3, 0.0f, 1.0f, 12);
    // Virtual points in front of a camera at the origin looking down -z, placed so that
    // last frame's camera (the same, or moved 0.05 to the right) sees each one at its
    // own pixel centre (or about half a pixel to the left).
    const auto virtualpos = makeImage(w, h, 3, [&](uint32_t x, uint32_t y, uint32_t c) {
        const float depth = 4.0f + 0.01f * float((x * 7 + y) % 9);
        return c == 0 ? (2.0f * (float(x) + 0.5f) / float(w) - 1.0f) * depth
                      : c == 1 ? (2.0f * (float(y) + 0.5f) / float(h) - 1.0f) * depth : -depth;
    });
    const auto offsets = randomImage(w, h, 3, -0.05f, 0.05f, 13);
    FloatImage virtualposHistory = virtualpos;
    for (size_t i = 0; i < virtualposHistory.pixels.size(); ++i) virtualposHistory.pixels[i] += offsets.pixels[i];
    // Projection (column-major): ndc = (x, y) / -z.
    auto camera = std::make_shared<passes::FrameCamera>();
    camera->previousProjection = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -1, 0, 0, 0.1f, 0};
    camera->previousView = passes::FrameCamera::kIdentity;
    camera->previousView[12] = -0.05f * float(GENERATE(0, 1));
    NodeHarness t({w, h});
    const auto vp = t.input("virtualpos", virtualpos);
    const auto out = passes::addMaraGlossyTemporalPass(t.ctx, "glossy", t.input("current", current), vp,
                                                       t.input("vp_history", virtualposHistory), camera);
    // The history is the node's own output: run once, overwrite nothing, compare frame 2.
    t.graph.markOutput(out);
    t.graph.execute();
    t.graph.waitIdle();
    const auto frame0 = readOutput(t.graph, out);
    const auto frame1 = t.runOnce(out);
    std::array<double, 16> m{};
    const auto vpMatrix = passes::multiply(camera->previousProjection, camera->previousView);
    for (size_t i = 0; i < 16; ++i) m[i] = vpMatrix[i];
    reference::MaraTemporalParams p;
    const auto ref = reference::maraGlossyTemporal(current, virtualpos, frame0, virtualposHistory, m, p);
    // Positions about 4 m from the origin differ by centimetres: their fp32 difference
    // is good to about 1e-6 m, which the smoothstep's slope (at most 75 per metre)
    // turns into 1e-4 of confidence.
    HUSH_REQUIRE_IMAGES_MATCH(frame1, ref, 2e-4f, 2e-5f);
    size_t reprojected = 0;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) reprojected += frame1.at(x, y, 3) > 0.0f;
    CHECK(reprojected > w * h / 4);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
