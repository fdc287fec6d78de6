// Compile step 2, cull: passes that reach no output, imported write, side effect or
// history are dropped and reported by name; everything they alone used goes too.
#include <catch2/catch.hpp>

#include <hush/graph/compile_steps.hpp>

#include "graph/graph_test_util.hpp"
#include "graph/model_builders.hpp"

using namespace hush;
using namespace hush::graph;
using namespace hush::graph_test;
using hush::test::gpu;
using hush::test::ValidationScope;
using Names = std::vector<std::string>;

TEST_CASE("cull: a hand-built model keeps what reaches the outside, transitively", "[graph][cull]") {
    GraphModel m;
    m.resources = {
        textureDecl("in", ResourceOrigin::Imported, 1),        // 0
        textureDecl("a", ResourceOrigin::Transient, 2),        // 1
        textureDecl("b", ResourceOrigin::Transient, 2),        // 2: output
        textureDecl("dead", ResourceOrigin::Transient, 2),     // 3
        textureDecl("deader", ResourceOrigin::Transient, 2),   // 4
        textureDecl("out", ResourceOrigin::Imported, 2),       // 5
        textureDecl("s", ResourceOrigin::Transient, 2),        // 6
        textureDecl("acc", ResourceOrigin::History, 1),        // 7
        textureDecl("acc", ResourceOrigin::Transient, 2),      // 8
        textureDecl("display", ResourceOrigin::Imported, 2),   // 9
        textureDecl("unused", ResourceOrigin::Transient, 2),   // 10
    };
    m.resources[7].historySource = 8;   // last frame's "acc"
    m.resources[2].output = true;
    m.passes = {
        passDecl("makeA", {readOf(0, 0), writeOf(1, 0)}),                // 0: b and others need a
        passDecl("makeB", {readOf(1, 1), writeOf(2, 0)}),                // 1: output
        passDecl("dead", {readOf(1, 1), writeOf(3, 0)}),                 // 2: read only by 'deader'
        passDecl("deader", {readOf(3, 1), writeOf(4, 0)}),               // 3: reaches nothing
        passDecl("export", {readOf(1, 1), writeOf(5, 0)}),               // 4: writes an imported texture
        passDecl("side", {readOf(1, 1), writeOf(6, 0)}, true),           // 5: side effect
        passDecl("display", {readOf(7, 0, "history"), writeOf(9, 0)}),   // 6: imported write, reads history
        passDecl("accumulate", {readOf(0, 0), writeOf(8, 0)}),           // 7: its result is next frame's history
        passDecl("unused", {readOf(0, 0), writeOf(10, 0)}),              // 8: reaches nothing
    };
    REQUIRE_NOTHROW(validate(m));
    const auto c = cull(m);
    CHECK(c.culled == std::vector<uint32_t>{2, 3, 8});
    CHECK(c.passAlive == std::vector<bool>{true, true, false, false, true, true, true, true, false});
    CHECK(c.resourceUsed == std::vector<bool>{true, true, true, false, false, true, true, true, true, true, false});

    // No reader of the history: its source's producer is dead weight too.
    m.passes[6].accesses[0].resource = 0;
    CHECK(cull(m).culled == std::vector<uint32_t>{2, 3, 7, 8});
    // Nothing marked at all: everything goes.
    m.resources[2].output = false;
    m.passes[4].accesses[1].resource = 6;   // 'export' now writes a transient
    m.passes[5].sideEffect = false;
    m.passes[6].accesses[1].resource = 10;
    CHECK(cull(m).culled == std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 6, 7, 8});
}

TEST_CASE("cull: a graph drops dead passes, reports them by name and never runs them", "[graph][cull][gpu]") {
    ValidationScope validation;
    const auto p = makePipelines();
    constexpr uint32_t kW = 40, kH = 32;
    auto exported = makeTexture("exported", kW, kH);

    RenderGraph g(gpu().device, {.label = "cull"});
    g.setOutputSize({kW, kH});
    const auto out = g.importTexture("exported", exported,
                                     {.initialState = ResourceState::Undefined, .finalState = ResourceState::CopySrc});
    const auto source = addFill(g, p, "source", 100);
    const auto kept = addCopy(g, p, "kept", source, 1);
    const auto dead1 = addCopy(g, p, "dead.1", source, 2);
    addCopy(g, p, "dead.2", dead1, 3);
    uint32_t sideRuns = 0, deadRuns = 0;
    g.addPass("side", [&](PassBuilder& b) {
        b.read("src", source);
        b.sideEffect();   // e.g. statistics for the application, read back elsewhere
        return [&](PassContext&) { ++sideRuns; };
    });
    g.addPass("dead.3", [&](PassBuilder& b) {
        b.read("src", kept);
        b.write("dst", b.create("dead.3", {.format = kFormat}));
        return [&](PassContext&) { ++deadRuns; };
    });
    addCopyInto(g, p, "export", source, out, 4);
    g.markOutput(kept);

    for (int frame = 0; frame < 3; ++frame) g.execute();
    g.waitIdle();

    CHECK(g.culledPasses() == Names{"dead.1", "dead.2", "dead.3"});
    CHECK(g.passOrder() == Names{"source", "kept", "side", "export"});
    CHECK(deadRuns == 0);
    CHECK(sideRuns == 3);
    // The step alone, on the graph's model, says the same.
    const auto c = cull(g.model());
    CHECK(c.culled == std::vector<uint32_t>{2, 3, 5});
    CHECK_FALSE(c.resourceUsed[dead1.index]);
    // What ran is what the timings list.
    Names timed;
    for (const auto& t : g.timings().passes) timed.push_back(t.name);
    CHECK(timed == g.passOrder());

    // The kept and exported results are right.
    CHECK(readOutput(g, kept) == fillImage(101, kW, kH));
    CHECK(download(exported, ResourceState::CopySrc) == fillImage(104, kW, kH));
    // Culled transients get no texture.
    CHECK_THROWS_AS(g.outputTexture(dead1), Error);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("cull: marking a dead branch as an output brings it back", "[graph][cull][gpu]") {
    ValidationScope validation;
    const auto p = makePipelines();
    RenderGraph g(gpu().device, {.label = "cull.revive"});
    g.setOutputSize({32, 32});
    const auto source = addFill(g, p, "source", 7);
    const auto main = addCopy(g, p, "main", source, 1);
    const auto glossy = addCopy(g, p, "glossy", source, 2);   // a scene without glossy surfaces
    g.markOutput(main);
    g.execute();
    CHECK(g.culledPasses() == Names{"glossy"});
    CHECK(g.compileCount() == 1);

    g.markOutput(glossy);   // the scene changed: now the branch is needed
    CHECK(g.needsCompile());
    g.execute();
    g.waitIdle();
    CHECK(g.compileCount() == 2);
    CHECK(g.culledPasses().empty());
    CHECK(g.passOrder() == Names{"source", "main", "glossy"});
    CHECK(readOutput(g, glossy) == fillImage(9, 32, 32));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
