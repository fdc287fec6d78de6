// RDAE 2x2 max pooling against the CPU: every channel, exact (a max copies a value).
#include <catch2/catch.hpp>

#include <hush/passes/rdae/pool.hpp>

#include "rdae_test_util.hpp"
#include "reference/rdae_pool.hpp"

using namespace hush;
using namespace hush::passes_test;

TEST_CASE("rdae pool takes the largest of each 2x2, every channel", "[rdae][rdae-pool]") {
    test::ValidationScope scope;
    for (const auto format : {rhi::Format::RGBA32Float, rhi::Format::RGBA16Float})
        for (const uint32_t channels : {3u, 8u, 43u}) {
            INFO(channels << " channels, " << rhi::toString(format));
            const passes::RdaeTensorFormat f{.levels = 1, .format = format};
            NodeHarness h({38, 30});
            // Values a half holds exactly: the comparison is exact in both formats.
            auto t = randomTensor(channels, 38, 30, -4.0f, 4.0f, channels);
            for (auto& v : t.values) v = std::round(v * 64.0f) / 64.0f;
            const auto out = passes::addRdaePoolPass(h.ctx, "pool", importTensor(h, "t", t, 0, f), f);
            HUSH_REQUIRE_TENSORS_MATCH(runTensor(h, out, 19, 15), reference::rdaePool(t), 0.0f, 0.0f);
        }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("rdae pool refuses to go below the network's deepest level", "[rdae][rdae-pool]") {
    const passes::RdaeTensorFormat f{.levels = 1, .format = rhi::Format::RGBA32Float};
    NodeHarness h({4, 4});
    const passes::RdaeTensor deepest{h.input("t", FloatImage(2, 2, 4)), 4, 1};
    REQUIRE_THROWS_WITH(passes::addRdaePoolPass(h.ctx, "pool", deepest, f), Catch::Contains("deepest"));
}
