// passes/common/taa, its history: the history filters (bilinear, Catmull-Rom) and
// the optional reprojection decision, against the CPU reference and against the
// exact images they should reproduce: no drift with a static camera, exact copies
// under whole-pixel motion, a smooth pattern translated by sub-pixel steps, and an
// aliased (point-sampled) edge moving over the pixel centres.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <hush/passes/common/taa.hpp>

#include "reference/common_reproject.hpp"
#include "reference/common_surface.hpp"
#include "reference/common_taa.hpp"
#include "taa_test_graph.hpp"

using namespace hush;
using namespace hush::passes_test;
using passes::TaaBox;
using passes::TaaHistoryFilter;
using passes::TaaSettings;

namespace {

const TaaSettings kCatmullRom{};   // the defaults
const TaaSettings kBilinear{.historyFilter = TaaHistoryFilter::Bilinear};

// GPU (fp32) against the double reference, as in test_common_taa.cpp: the blend
// shrinks last frame's error by 1 - alpha, so the feedback does not let it grow.
constexpr float kAbsTol = 2e-6f, kRelTol = 2e-6f;

// A decision in reproject.hpp's encoding for `motion`, drawn at random: 10 % of the
// pixels disoccluded, 20 % a 3x3 fallback, the rest 2x2 bilinear at the previous
// position, half of those whole (every tap of positive weight usable), half with
// some taps left out. Only taps inside the image are ever set, as the node does.
FloatImage randomDecision(const FloatImage& motion, uint64_t seed) {
    const int w = int(motion.width), h = int(motion.height);
    const auto dice = randomImage(motion.width, motion.height, 3, 0.0f, 1.0f, seed);
    FloatImage d(motion.width, motion.height, 4, 0.0f);
    auto inside = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h; };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const auto ux = uint32_t(x), uy = uint32_t(y);
            const float px = float(x) + motion.at(ux, uy, 0), py = float(y) + motion.at(ux, uy, 1);
            const int bx = int(std::floor(px)), by = int(std::floor(py));
            const float kind = dice.at(ux, uy, 0);
            uint32_t mask = 0, mode = 0;
            if (kind >= 0.3f) {   // 2x2 bilinear: taps of positive weight, all or some
                mode = 1;
                const bool wx = px > float(bx), wy = py > float(by);
                for (int j = 0; j < 2; ++j)
                    for (int i = 0; i < 2; ++i) {
                        const bool positive = (i == 0 || wx) && (j == 0 || wy);
                        const bool keep = dice.at(ux, uy, 1) < 0.5f || dice.at(ux, uy, 2) * 4.0f > float(j * 2 + i);
                        if (positive && keep && inside(bx + i, by + j)) mask |= 1u << uint32_t(j * 2 + i);
                    }
                d.at(ux, uy, 0) = px, d.at(ux, uy, 1) = py;
            } else if (kind >= 0.1f) {   // 3x3 fallback around the previous position
                mode = 2;
                const auto bits = uint32_t(dice.at(ux, uy, 1) * 511.0f) + 1u;
                for (int k = 0; k < 9; ++k)
                    if (((bits >> uint32_t(k)) & 1u) && inside(bx - 1 + k % 3, by - 1 + k / 3)) mask |= 1u << uint32_t(k);
                d.at(ux, uy, 0) = float(bx - 1), d.at(ux, uy, 1) = float(by - 1);
            }
            d.at(ux, uy, 2) = float(mask);
            d.at(ux, uy, 3) = float(mode);
        }
    return d;
}

// A smooth colour pattern (periods 7 to 11 px, values in [0.1, 0.9]) at continuous
// position (u, v) in pixels.
void smoothPattern(double u, double v, float rgb[3]) {
    const double tau = 2.0 * std::numbers::pi;
    const double g = 0.5 + 0.25 * std::sin(tau * u / 7.0) * std::sin(tau * v / 9.0) + 0.1 * std::cos(tau * (u + v) / 11.0);
    rgb[0] = float(g);
    rgb[1] = float(0.3 + 0.5 * g * g);
    rgb[2] = float(1.0 - g);
}

// RMSE of rgb over [x0, x1) x [y0, y1).
double rmse(const FloatImage& a, const FloatImage& b, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1) {
    double sum = 0.0;
    for (uint32_t y = y0; y < y1; ++y)
        for (uint32_t x = x0; x < x1; ++x)
            for (uint32_t c = 0; c < 3; ++c) sum += std::pow(double(a.at(x, y, c)) - double(b.at(x, y, c)), 2.0);
    return std::sqrt(sum / (3.0 * (x1 - x0) * (y1 - y0)));
}

double maxAbsDiff(const FloatImage& a, const FloatImage& b) {
    double worst = 0.0;
    for (uint32_t y = 0; y < a.height; ++y)
        for (uint32_t x = 0; x < a.width; ++x)
            for (uint32_t c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(a.at(x, y, c)) - b.at(x, y, c)));
    return worst;
}

} // namespace

TEST_CASE("TAA reads its history through a reprojection decision as the CPU reference does", "[common][taa]") {
    test::ValidationScope scope;
    const rhi::Extent2D size{27, 19};
    const auto motion = randomImage(size.width, size.height, 2, -1.5f, 1.5f, 800);
    const TaaSettings variance{.box = TaaBox::Variance};
    for (const auto& settings : {kCatmullRom, kBilinear, variance}) {
        INFO(describe(settings));
        TaaGraph gpu(size, settings, true);
        reference::Taa ref(settings);
        for (uint32_t f = 0; f < 5; ++f) {
            const auto decision = randomDecision(motion, 810 + f);
            const auto current = randomImage(size.width, size.height, 4, 0.0f, 1.0f, 820 + f);
            INFO("frame " << f);
            const auto out = gpu.frame(current, motion, decision);
            HUSH_REQUIRE_IMAGES_MATCH(out, ref.frame(current, motion, decision), kAbsTol, kRelTol, 3);
            // A disoccluded pixel outputs the current colour, exactly.
            for (uint32_t y = 0; y < size.height; ++y)
                for (uint32_t x = 0; x < size.width; ++x)
                    if (decision.at(x, y, 3) == 0.0f || decision.at(x, y, 2) == 0.0f)
                        for (uint32_t c = 0; c < 3; ++c) REQUIRE(out.at(x, y, c) == current.at(x, y, c));
        }
    }
    SECTION("at 1e-30, 65504 and 1e6") {
        for (float scale : {1e-30f, 65504.0f, 1e6f}) {
            INFO("scale " << scale);
            TaaGraph gpu(size, {}, true);
            reference::Taa ref({});
            for (uint32_t f = 0; f < 3; ++f) {
                const auto decision = randomDecision(motion, 830 + f);
                const auto current = randomImage(size.width, size.height, 4, 0.0f, scale, 840 + f);
                const auto out = gpu.frame(current, motion, decision);
                REQUIRE(nonFiniteCount(out) == 0);
                HUSH_REQUIRE_IMAGES_MATCH(out, ref.frame(current, motion, decision), 4e-6f * scale, kRelTol, 3);
            }
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("TAA does not drift with a static camera", "[common][taa]") {
    test::ValidationScope scope;
    const rhi::Extent2D size{21, 13};
    const auto still = constantMotion(size, 0.0f, 0.0f);
    const auto image = randomImage(size.width, size.height, 4, 0.0f, 1.0f, 900);
    const auto flat = FloatImage(size.width, size.height, 4, 0.375f);
    const auto identity = reference::identityDecision(size.width, size.height);
    for (const auto& settings : {kCatmullRom, kBilinear}) {
        for (bool withDecision : {false, true}) {
            INFO(describe(settings) << (withDecision ? " with the identity decision" : ""));
            TaaGraph gpu(size, settings, withDecision);
            reference::Taa ref(settings);
            const FloatImage decision = withDecision ? identity : FloatImage{};
            // 60 frames (6 time constants of the blend) of one image: the output stays
            // on it; the YCoCg round trip and the blend only round (measured 2.4e-7).
            for (uint32_t f = 0; f < 60; ++f) {
                INFO("frame " << f);
                const auto out = gpu.frame(image, still, decision);
                HUSH_REQUIRE_IMAGES_MATCH(out, image, 5e-7f, 0.0f, 3);
                if (f % 10 == 9) HUSH_REQUIRE_IMAGES_MATCH(out, ref.frame(image, still, decision), kAbsTol, kRelTol, 3);
                else ref.frame(image, still, decision);
            }
            // A flat grey stays itself up to the blend's rounding (mix(x, x, a) need not
            // be x in fp32; measured 3e-8).
            for (uint32_t f = 0; f < 5; ++f) HUSH_REQUIRE_IMAGES_MATCH(gpu.frame(flat, still, decision), flat, 1e-7f, 0.0f, 3);
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("TAA copies the history exactly under whole-pixel motion", "[common][taa]") {
    test::ValidationScope scope;
    const rhi::Extent2D size{25, 17};
    // The content moves by (2, -1) px a frame: previous position = current + (-2, 1).
    // Random (unfiltered, worst-case) content, so any blur would show.
    const auto texture = randomImage(size.width + 40, size.height + 20, 4, 0.0f, 1.0f, 950);
    auto frameAt = [&](uint32_t f) {
        return makeImage(size.width, size.height, 4, [&](uint32_t x, uint32_t y, uint32_t c) {
            return texture.at(x + 30 - 2 * f, y + f, c);
        });
    };
    const auto motion = constantMotion(size, -2.0f, 1.0f);
    for (const auto& settings : {kCatmullRom, kBilinear}) {
        INFO(describe(settings));
        TaaGraph gpu(size, settings);
        reference::Taa ref(settings);
        for (uint32_t f = 0; f < 12; ++f) {
            INFO("frame " << f);
            const auto current = frameAt(f);
            const auto out = gpu.frame(current, motion);
            HUSH_REQUIRE_IMAGES_MATCH(out, ref.frame(current, motion), kAbsTol, kRelTol, 3);
            // Catmull-Rom's weights at a whole-pixel position are exactly (0, 1, 0, 0):
            // only the YCoCg round trip and the blend round (measured 2.4e-7).
            HUSH_REQUIRE_IMAGES_MATCH(out, current, 5e-7f, 0.0f, 3);
        }
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("Catmull-Rom history keeps a smooth pattern moving by sub-pixel steps close to the truth",
          "[common][taa]") {
    test::ValidationScope scope;
    // The pattern moves by v = (0.43, 0.27) px a frame; frame f is it point-sampled at
    // the pixel centres (smooth, so there is no aliasing: every frame is exact and a
    // perfect TAA would return it unchanged). The history's blur is what remains.
    const rhi::Extent2D size{48, 40};
    const double vx = 0.43, vy = 0.27;
    auto frameAt = [&](uint32_t f) {
        FloatImage image(size.width, size.height, 4, 1.0f);
        for (uint32_t y = 0; y < size.height; ++y)
            for (uint32_t x = 0; x < size.width; ++x)
                smoothPattern(x + 0.5 - vx * f, y + 0.5 - vy * f, &image.at(x, y, 0));
        return image;
    };
    const auto motion = constantMotion(size, float(-vx), float(-vy));
    // The left and top edges feed repeated edge texels into the history, which the
    // motion carries inwards by 20 v = (8.6, 5.4) px in 20 frames: scored inside them.
    const uint32_t x0 = 10, y0 = 7, x1 = size.width - 3, y1 = size.height - 3;
    double error[2] = {0.0, 0.0};
    int k = 0;
    for (const auto& settings : {kCatmullRom, kBilinear}) {
        INFO(describe(settings));
        TaaGraph gpu(size, settings);
        reference::Taa ref(settings);
        FloatImage out, truth;
        for (uint32_t f = 0; f < 20; ++f) {
            truth = frameAt(f);
            out = gpu.frame(truth, motion);
            INFO("frame " << f);
            HUSH_REQUIRE_IMAGES_MATCH(out, ref.frame(truth, motion), kAbsTol, kRelTol, 3);
        }
        error[k++] = rmse(out, truth, x0, y0, x1, y1);
    }
    INFO("RMSE after 20 frames: Catmull-Rom " << error[0] << ", bilinear " << error[1]);
    // Measured: Catmull-Rom 0.0150, bilinear 0.0632 (values in [0.1, 0.9]). Neither
    // is 0: a filter of response H(w) per frame leaves the steady state at
    // alpha / (1 - (1 - alpha) H(w)) of the truth; at this step, for the 7 px period,
    // |H| = 0.986 (Catmull-Rom) gives 11 % loss, |H| = 0.903 (bilinear) 47 %.
    CHECK(error[0] < 0.02);
    CHECK(error[0] < 0.3 * error[1]);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("A reprojection decision stops TAA lagging behind an aliased moving edge", "[common][taa]") {
    test::ValidationScope scope;
    // An object (mesh 0, colour a) left of x = 10.2 + 0.3 f moves right over a static
    // background (mesh 1, colour b), point-sampled at the pixel centres like frames
    // rendered without jitter. When the edge passes a pixel centre the pixel turns
    // from b to a; its history, 0.3 px to the left, is still mostly last frame's b,
    // and both colours are in its 3x3 neighbourhood, so rectification keeps it.
    const rhi::Extent2D size{32, 12};
    const float a[3] = {0.8f, 0.25f, 0.1f}, b[3] = {0.1f, 0.3f, 0.7f};
    auto edgeAt = [](uint32_t f) { return 10.2 + 0.3 * f; };
    auto onObject = [&](uint32_t x, uint32_t f) { return x + 0.5 < edgeAt(f); };
    auto surfaceAt = [&](uint32_t f) {
        reference::SurfaceImages s{FloatImage(size.width, size.height, 4, 0.0f), FloatImage(size.width, size.height, 4, 0.0f)};
        for (uint32_t y = 0; y < size.height; ++y)
            for (uint32_t x = 0; x < size.width; ++x) {
                s.normalDepth.at(x, y, 2) = 1.0f;   // normal +z, depth 1 everywhere: only the mesh id differs
                s.normalDepth.at(x, y, 3) = 1.0f;
                s.gradientMesh.at(x, y, 2) = onObject(x, f) ? 0.0f : 1.0f;
            }
        return s;
    };
    for (const auto& settings : {kCatmullRom, kBilinear}) {
        INFO(describe(settings));
        TaaGraph plain(size, settings), decided(size, settings, true);
        reference::Taa ref(settings), refPlain(settings);
        double lagWithout = 0.0, lagWith = 0.0;
        reference::SurfaceImages previous = surfaceAt(0);
        for (uint32_t f = 0; f < 12; ++f) {
            const auto current = makeImage(size.width, size.height, 4, [&](uint32_t x, uint32_t, uint32_t c) {
                return c < 3 ? (onObject(x, f) ? a[c] : b[c]) : 1.0f;
            });
            const auto motion = makeImage(size.width, size.height, 2, [&](uint32_t x, uint32_t, uint32_t c) {
                return c == 0 && onObject(x, f) ? -0.3f : 0.0f;
            });
            const auto surface = surfaceAt(f);
            const auto decision = reference::reproject(motion, surface, previous, {}, f > 0);
            previous = surface;
            INFO("frame " << f);
            const auto out = decided.frame(current, motion, decision);
            HUSH_REQUIRE_IMAGES_MATCH(out, ref.frame(current, motion, decision), kAbsTol, kRelTol, 3);
            lagWith = std::max(lagWith, maxAbsDiff(out, current));
            const auto plainOut = plain.frame(current, motion);
            HUSH_REQUIRE_IMAGES_MATCH(plainOut, refPlain.frame(current, motion), kAbsTol, kRelTol, 3);
            lagWithout = std::max(lagWithout, maxAbsDiff(plainOut, current));
        }
        INFO("largest |output - current|: without a decision " << lagWithout << ", with " << lagWith);
        // Without: the pixels the edge has just crossed keep mostly the background
        // (red differs by 0.7; measured 0.52 Catmull-Rom, 0.49 bilinear). With: the
        // background's taps are left out (measured 1.2e-7).
        CHECK(lagWithout > 0.3);
        CHECK(lagWith < 1e-6);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
