// The RDAE input tensor against the CPU: colour^0.2 (negatives to 0), normals rotated
// into view space by the frame's camera, depth in metres mapped to d / (1 + d),
// roughness clamped; padded to the pooling multiple by repeating the edges.
#include <catch2/catch.hpp>

#include <cmath>

#include <hush/passes/rdae/input.hpp>

#include "rdae_test_util.hpp"
#include "reference/rdae_input.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

// A rotation about an oblique axis (column-major), as a camera's view would hold.
std::array<float, 16> rotation(float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    // Rotation about (1, 1, 1) / sqrt(3): Rodrigues' formula.
    const float t = 1.0f - c, k = 1.0f / std::sqrt(3.0f), x = k, y = k, z = k;
    return {t * x * x + c,     t * x * y + s * z, t * x * z - s * y, 0,
            t * x * y - s * z, t * y * y + c,     t * y * z + s * x, 0,
            t * x * z + s * y, t * y * z - s * x, t * z * z + c,     0,
            0.3f,              -2.0f,             5.0f,              1};
}

Tensor gpuInput(const FloatImage& illumination, const FloatImage& normal, const FloatImage& depth,
                const FloatImage& roughness, const passes::FrameCamera& camera, const passes::RdaeTensorFormat& f) {
    NodeHarness h({illumination.width, illumination.height});
    const auto ref = std::make_shared<const passes::FrameCamera>(camera);
    const auto t = passes::addRdaeInputPass(h.ctx, "input", h.input("illumination", illumination),
                                            h.input("normal", normal), h.input("depth", depth),
                                            h.input("roughness", roughness), ref, f);
    const uint32_t m = 1u << f.levels;
    return runTensor(h, t, (illumination.width + m - 1) / m * m, (illumination.height + m - 1) / m * m);
}

} // namespace

TEST_CASE("rdae input matches the CPU, padded by repeating the edges", "[rdae][rdae-input]") {
    test::ValidationScope scope;
    passes::FrameCamera camera;
    camera.view = rotation(0.7f);
    camera.metresPerUnit = 0.001f;   // millimetres, like the Cornell box
    for (const auto size : {rhi::Extent2D{1, 1}, rhi::Extent2D{37, 29}}) {
        INFO(size.width << "x" << size.height);
        const auto illumination = randomImage(size.width, size.height, 4, -1.0f, 50.0f, 1);
        auto normal = randomImage(size.width, size.height, 4, -1.0f, 1.0f, 2);
        for (uint32_t i = 0; i < size.width * size.height; ++i) {
            float* n = &normal.pixels[i * 4];
            const float l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) + 1e-6f;
            for (int c = 0; c < 3; ++c) n[c] /= l;
        }
        const auto depth = randomImage(size.width, size.height, 4, 100.0f, 20000.0f, 3);
        const auto roughness = randomImage(size.width, size.height, 4, -0.5f, 1.5f, 4);
        const passes::RdaeTensorFormat f{.levels = 2, .format = rhi::Format::RGBA32Float};
        const auto ref = reference::rdaeInput(illumination, normal, depth, roughness, camera.view, 0.001f, 2);
        HUSH_REQUIRE_TENSORS_MATCH(gpuInput(illumination, normal, depth, roughness, camera, f), ref, 1e-5f, 1e-5f);
        const passes::RdaeTensorFormat half{.levels = 2, .format = rhi::Format::RGBA16Float};
        HUSH_REQUIRE_TENSORS_MATCH(gpuInput(illumination, normal, depth, roughness, camera, half), ref, 1e-3f, 1e-3f);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("rdae input needs the frame's camera", "[rdae][rdae-input]") {
    NodeHarness h({4, 4});
    const auto t = h.input("t", FloatImage(4, 4, 4));
    REQUIRE_THROWS_WITH(passes::addRdaeInputPass(h.ctx, "rdae.input", t, t, t, t, nullptr, {}),
                        Catch::Contains("rdae.input") && Catch::Contains("camera"));
}
