// passes/common/remodulate: the inverse of demodulation (passes/common/demodulate)
// over one and two filtered terms.
#include <catch2/catch.hpp>

#include <hush/passes/common/demodulate.hpp>
#include <hush/passes/common/remodulate.hpp>

#include "pass_test_util.hpp"

using namespace hush;
using namespace hush::passes_test;

TEST_CASE("remodulate inverts demodulate over one and two terms", "[common][demodulate]") {
    test::ValidationScope scope;
    const uint32_t w = 16, h = 9;
    auto direct = randomImage(w, h, 4, 0.0f, 5.0f, 3);
    auto indirect = randomImage(w, h, 4, 0.0f, 5.0f, 4);
    auto albedo = randomImage(w, h, 4, 0.0f, 1.0f, 5);
    for (uint32_t c = 0; c < 3; ++c) albedo.at(3, 3, c) = 0.0f;

    NodeHarness t({w, h});
    auto alb = t.input("albedo", albedo);
    auto d = passes::addDemodulatePass(t.ctx, "demod.direct", t.input("direct", direct), alb);
    auto i = passes::addDemodulatePass(t.ctx, "demod.indirect", t.input("indirect", indirect), alb);
    auto both = passes::addRemodulatePass(t.ctx, "remod.both", d, i, alb);
    auto one = passes::addRemodulatePass(t.ctx, "remod.one", d, {}, alb);
    t.graph.markOutput(one);
    auto gpuBoth = t.runOnce(both);
    auto gpuOne = readOutput(t.graph, one);

    FloatImage sum = direct;
    for (size_t k = 0; k < sum.pixels.size(); ++k) sum.pixels[k] += indirect.pixels[k];
    HUSH_REQUIRE_IMAGES_MATCH(gpuBoth, sum, 1e-5f, 1e-5f, 3);
    HUSH_REQUIRE_IMAGES_MATCH(gpuOne, direct, 1e-5f, 1e-5f, 3);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
