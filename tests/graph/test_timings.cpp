// Per-pass GPU timings: one for every executed pass, non-negative, summing to no
// more than the frame's total; read from the oldest frame in flight, so reading them
// never waits for the GPU.
#include <catch2/catch.hpp>

#include <cmath>

#include "graph/graph_test_util.hpp"

using namespace hush;
using namespace hush::graph;
using namespace hush::graph_test;
using hush::test::gpu;
using hush::test::ValidationScope;

namespace {

// fill -> 5 combines -> output, plus one culled pass.
void buildChain(RenderGraph& g, const Pipelines& p) {
    g.setOutputSize({96, 64});
    auto a = addFill(g, p, "fill", 1);
    auto b = a;
    for (uint32_t i = 0; i < 5; ++i) {
        auto next = addCombine(g, p, "combine." + std::to_string(i), a, b, {i + 1, i + 2, i + 3, 1});
        b = a;
        a = next;
    }
    addCopy(g, p, "culled", a, 1);
    g.markOutput(a);
}

} // namespace

TEST_CASE("timings: every executed pass is timed, non-negative, within the total", "[graph][timings][gpu]") {
    ValidationScope validation;
    REQUIRE(gpu().device.adapterInfo().limits.timestampsSupported);
    const auto p = makePipelines();
    RenderGraph g(gpu().device, {.label = "timings"});
    buildChain(g, p);
    g.compile();
    CHECK_FALSE(g.timings().valid);   // no frame has completed yet

    for (int frame = 0; frame < 4; ++frame) g.execute();
    g.waitIdle();
    const auto& t = g.timings();
    REQUIRE(t.valid);
    CHECK(t.frame == g.frameCount() - 1);   // waitIdle leaves the newest frame's timings
    const auto order = g.passOrder();
    REQUIRE(t.passes.size() == order.size());
    REQUIRE(order.size() == 6);   // 'culled' is not timed: it does not run
    double sum = 0.0;
    for (size_t i = 0; i < order.size(); ++i) {
        INFO("pass " << t.passes[i].name << ": " << t.passes[i].gpuMs << " ms");
        CHECK(t.passes[i].name == order[i]);
        CHECK(std::isfinite(t.passes[i].gpuMs));
        CHECK(t.passes[i].gpuMs >= 0.0);
        sum += t.passes[i].gpuMs;
    }
    INFO("sum of passes " << sum << " ms, total " << t.totalGpuMs << " ms");
    CHECK(std::isfinite(t.totalGpuMs));
    CHECK(t.totalGpuMs > 0.0);
    // The passes are disjoint intervals inside the frame's: their tick counts sum to at
    // most the total's. Converting ticks to ms rounds each term, hence the 1e-9 relative slack.
    CHECK(sum <= t.totalGpuMs * (1.0 + 1e-9));
    CHECK(t.cpuRecordMs >= 0.0);
    CHECK(std::isfinite(t.cpuRecordMs));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("timings: they come from the oldest frame in flight, without waiting", "[graph][timings][gpu]") {
    ValidationScope validation;
    const auto p = makePipelines();
    for (const uint32_t inFlight : {1u, 2u, 3u}) {
        INFO(inFlight << " frames in flight");
        RenderGraph g(gpu().device, {.label = "timings.inflight", .framesInFlight = inFlight});
        buildChain(g, p);
        // A frame's timings are read when its slot comes round again (or at waitIdle).
        for (uint32_t frame = 0; frame < inFlight; ++frame) {
            g.execute();
            CHECK_FALSE(g.timings().valid);
        }
        for (uint32_t frame = inFlight; frame < inFlight + 4; ++frame) {
            g.execute();
            REQUIRE(g.timings().valid);
            CHECK(g.timings().frame == frame - inFlight);
        }
        g.waitIdle();
        CHECK(g.timings().frame == inFlight + 3);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
