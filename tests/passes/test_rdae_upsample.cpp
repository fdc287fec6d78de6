// RDAE 2x2 nearest upsampling against the CPU: every channel, exact.
#include <catch2/catch.hpp>

#include <hush/passes/rdae/upsample.hpp>

#include "rdae_test_util.hpp"
#include "reference/rdae_upsample.hpp"

using namespace hush;
using namespace hush::passes_test;

TEST_CASE("rdae upsample repeats each value over 2x2, every channel", "[rdae][rdae-upsample]") {
    test::ValidationScope scope;
    for (const uint32_t channels : {3u, 21u}) {
        INFO(channels << " channels");
        const passes::RdaeTensorFormat f{.levels = 1, .format = rhi::Format::RGBA32Float};
        NodeHarness h({38, 30});
        const auto t = randomTensor(channels, 19, 15, -4.0f, 4.0f, channels + 1);
        const auto out = passes::addRdaeUpsamplePass(h.ctx, "upsample", importTensor(h, "t", t, 1, f), f);
        HUSH_REQUIRE_TENSORS_MATCH(runTensor(h, out, 38, 30), reference::rdaeUpsample(t), 0.0f, 0.0f);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
