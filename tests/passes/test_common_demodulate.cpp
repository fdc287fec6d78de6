// passes/common/demodulate: demodulation against the CPU reference; black albedo keeps
// its radiance. Remodulation, demodulation's inverse: test_common_remodulate.cpp.
#include <catch2/catch.hpp>

#include <hush/passes/common/demodulate.hpp>

#include "reference/common_demodulate.hpp"

using namespace hush;
using namespace hush::passes_test;

TEST_CASE("demodulate matches the CPU reference, black albedo keeps its radiance", "[common][demodulate]") {
    test::ValidationScope scope;
    const uint32_t w = 37, h = 23;
    auto radiance = randomImage(w, h, 4, 0.0f, 20.0f, 1);
    auto albedo = randomImage(w, h, 4, 0.0f, 1.0f, 2);
    // Black (emitter-like) pixels, and one with one dark channel only.
    for (uint32_t x = 0; x < 5; ++x)
        for (uint32_t c = 0; c < 3; ++c) albedo.at(x, 0, c) = 0.0f;
    albedo.at(7, 3, 1) = 0.0f;
    const float eps = 1e-3f;

    NodeHarness t({w, h});
    auto illum = passes::addDemodulatePass(t.ctx, "demodulate", t.input("radiance", radiance),
                                           t.input("albedo", albedo), {.eps = eps});
    auto gpu = t.runOnce(illum);
    auto ref = reference::demodulate(radiance, albedo, eps);
    // One fp32 division each side: a few ulps.
    HUSH_REQUIRE_IMAGES_MATCH(gpu, ref, 0.0f, 1e-6f, 3);
    CHECK(gpu.at(2, 0, 0) == radiance.at(2, 0, 0));
    CHECK(gpu.at(7, 3, 1) == Approx(radiance.at(7, 3, 1) / eps));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
