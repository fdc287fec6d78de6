// The RDAE output node against the CPU: crop to the frame, x^5 of the clamped
// non-negative part, NaN to 0, never above 65504.
#include <catch2/catch.hpp>

#include <limits>

#include <hush/passes/rdae/output.hpp>

#include "rdae_test_util.hpp"
#include "reference/rdae_output.hpp"

using namespace hush;
using namespace hush::passes_test;

TEST_CASE("rdae output crops, undoes the 0.2 power and stays finite", "[rdae][rdae-output]") {
    test::ValidationScope scope;
    auto t = randomTensor(3, 40, 32, -1.0f, 3.0f, 9);
    t.at(0, 1, 1) = 20.0f;                                        // 20^5: clamped
    t.at(1, 2, 2) = std::numeric_limits<float>::quiet_NaN();      // a network gone wrong
    NodeHarness h({37, 29});
    const passes::RdaeTensorFormat f{.levels = 2, .format = rhi::Format::RGBA32Float};
    const auto out = h.runOnce(passes::addRdaeOutputPass(h.ctx, "output", importTensor(h, "t", t, 0, f)));
    HUSH_REQUIRE_IMAGES_MATCH(out, reference::rdaeOutput(t, 37, 29), 1e-6f, 1e-5f);
    CHECK(out.at(1, 1, 0) == 65504.0f);
    CHECK(out.at(2, 2, 1) == 0.0f);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
