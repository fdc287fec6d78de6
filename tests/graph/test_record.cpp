// RenderGraph::record: a frame recorded into the caller's command buffer (an engine's)
// computes what execute() computes, reports its timings once the caller says it
// finished, and refuses to run ahead of frames the caller has not reported.
#include <catch2/catch.hpp>

#include "graph/graph_test_util.hpp"

using namespace hush;
using namespace hush::graph;
using namespace hush::graph_test;
using hush::test::gpu;
using hush::test::ValidationScope;

namespace {

constexpr uint32_t kW = 24, kH = 16;

// fill -> copy(+7) into an output the application reads.
struct SmallGraph {
    Pipelines p = makePipelines();
    RenderGraph g{gpu().device, {.label = "record", .framesInFlight = 2}};
    TextureHandle out;
    SmallGraph() {
        g.setOutputSize({kW, kH});
        out = addCopy(g, p, "copy", addFill(g, p, "fill", 5), 7);
        g.markOutput(out);
    }
};

// The engine's side: its own encoder, its own submission, its own wait.
void recordAndSubmit(RenderGraph& graph) {
    rhi::CommandEncoder engine = gpu().device.createCommandEncoder({.label = "engine.frame"});
    graph.record(engine);
    auto queue = gpu().device.queue();
    queue.wait(queue.submit(engine.finish()));
}

} // namespace

TEST_CASE("record: frames recorded into the caller's encoder compute what execute computes", "[graph][record][gpu]") {
    ValidationScope validation;
    SmallGraph executed, recorded;
    for (int frame = 0; frame < 3; ++frame) {
        executed.g.execute();
        executed.g.waitIdle();
        recordAndSubmit(recorded.g);
        recorded.g.frameCompleted();
        CHECK(readOutput(recorded.g, recorded.out) == readOutput(executed.g, executed.out));
    }
    CHECK(readOutput(recorded.g, recorded.out)[0] == fillReference(5, 0, 0) + 7);
    if (gpu().device.adapterInfo().limits.timestampsSupported) {
        const GraphTimings& t = recorded.g.timings();
        REQUIRE(t.valid);
        CHECK(t.frame == 2);
        REQUIRE(t.passes.size() == 2);
        CHECK(t.totalGpuMs >= 0.0);
    }
}

TEST_CASE("record: running ahead of unreported frames and recompiling under them are refused", "[graph][record][gpu]") {
    ValidationScope validation;
    SmallGraph s;
    CHECK_THAT(errorMessage([&] { s.g.frameCompleted(); }), Catch::Contains("without a frame recorded"));
    recordAndSubmit(s.g);
    recordAndSubmit(s.g);   // two in flight: framesInFlight
    CHECK_THAT(errorMessage([&] { recordAndSubmit(s.g); }), Catch::Contains("frameCompleted()"));
    CHECK_THAT(errorMessage([&] { s.g.execute(); }), Catch::Contains("not reported finished"));
    s.g.setOutputSize({kW + 1, kH});   // a resize recompiles
    CHECK_THAT(errorMessage([&] { s.g.compile(); }), Catch::Contains("compile() while frame 0"));
    s.g.frameCompleted();
    s.g.frameCompleted();
    s.g.execute();   // all reported: execute and compile go on
    s.g.waitIdle();
    CHECK(readOutput(s.g, s.out).size() == size_t(kW + 1) * kH);
}
