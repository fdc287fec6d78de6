// Compile step 5, barriers: planned once, batched per pass, only where there is a
// hazard. Two passes that only read one texture in one layout get none between them.
#include <catch2/catch.hpp>

#include <hush/graph/compile_steps.hpp>

#include "graph/graph_test_util.hpp"
#include "graph/model_builders.hpp"

using namespace hush;
using namespace hush::graph;
using namespace hush::graph_test;
using hush::test::gpu;
using hush::test::ValidationScope;

namespace {

size_t barriersOn(const std::vector<PlannedBarrier>& list, uint32_t resource) {
    size_t n = 0;
    for (const auto& b : list) n += b.resource == resource;
    return n;
}

} // namespace

TEST_CASE("barriers: two readers of one texture get no barrier between them", "[graph][barriers][gpu]") {
    // in -> A -> t;  t -> B -> u;  t -> C -> v;  (u, v) -> D -> out (imported)
    // Planned, resource by resource:
    //   in   imported StorageRead -> read by A in StorageRead, final StorageRead: none
    //   t    discard before A (written), one before B (write -> read), none before C (read -> read)
    //   u    discard before B, one before D;  v: discard before C, one before D
    //   out  Undefined -> StorageWrite before D, StorageWrite -> CopySrc at the frame's end
    // 8 in all: A 1, B 2, C 1, D 3, frame end 1.
    ValidationScope validation;
    const auto p = makePipelines();
    constexpr uint32_t kW = 48, kH = 40;
    auto input = makeTexture("input", kW, kH);
    auto result = makeTexture("result", kW, kH);
    upload(input, fillImage(3, kW, kH), ResourceState::Undefined, ResourceState::StorageRead);

    for (const bool aliasing : {true, false}) {
        INFO("aliasing " << aliasing);
        RenderGraph g(gpu().device, {.label = "barriers", .aliasing = aliasing});
        g.setOutputSize({kW, kH});
        const auto in = g.importTexture(
            "input", input, {.initialState = ResourceState::StorageRead, .finalState = ResourceState::StorageRead});
        const auto out = g.importTexture(
            "result", result, {.initialState = ResourceState::Undefined, .finalState = ResourceState::CopySrc});
        const auto t = addCopy(g, p, "A", in, 1);
        const auto u = addCopy(g, p, "B", t, 2);
        const auto v = addCopy(g, p, "C", t, 3);
        g.addPass("D", [&](PassBuilder& b) {
            b.read("a", u);
            b.read("b", v);
            b.write("dst", out);
            const auto group = b.bindGroup(p.combine);
            return [=, pipeline = p.combine, params = combineParams(p.combine, {3, 5, 7, 2})](PassContext& ctx) {
                ctx.dispatch(pipeline, group, {kW, kH}, params);
            };
        });
        g.compile();
        REQUIRE(g.passOrder() == std::vector<std::string>{"A", "B", "C", "D"});
        CHECK(g.barrierCount() == 8);

        // The step alone: the same plan, and where each barrier is.
        const auto& m = g.model();
        const auto o = order(m, cull(m));
        const auto plan = planBarriers(m, o, std::vector<bool>(m.resources.size(), false));
        CHECK(plan.count() == 8);
        REQUIRE(plan.beforePass.size() == 4);
        CHECK(plan.beforePass[0].size() == 1);
        CHECK(plan.beforePass[1].size() == 2);
        CHECK(plan.beforePass[2].size() == 1);
        CHECK(plan.beforePass[3].size() == 3);
        CHECK(plan.frameEnd.size() == 1);
        CHECK(barriersOn(plan.beforePass[0], in.index) == 0);
        CHECK(barriersOn(plan.beforePass[1], t.index) == 1);   // t written by A, now read
        CHECK(barriersOn(plan.beforePass[2], t.index) == 0);   // read again: no hazard
        CHECK(barriersOn(plan.beforePass[3], out.index) == 1);
        const auto& first = plan.beforePass[0].front();
        CHECK(first.resource == t.index);
        CHECK(first.discard);
        CHECK(first.after == ResourceState::StorageWrite);
        CHECK(plan.frameEnd.front().resource == out.index);
        CHECK(plan.frameEnd.front().before == ResourceState::StorageWrite);
        CHECK(plan.frameEnd.front().after == ResourceState::CopySrc);

        // And the frames run clean under synchronization validation, with the right result.
        for (int frame = 0; frame < 3; ++frame) g.execute();
        g.waitIdle();
        CHECK(g.compileCount() == 1);
        std::vector<uint32_t> expected(size_t(kW) * kH);
        const auto src = fillImage(3, kW, kH);
        for (uint32_t y = 0; y < kH; ++y)
            for (uint32_t x = 0; x < kW; ++x) {
                const size_t i = size_t(y) * kW + x;
                expected[i] = combineReference(src[i] + 3, src[i] + 4, {3, 5, 7, 2}, x, y);
            }
        CHECK(download(result, ResourceState::CopySrc) == expected);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("barriers: planned on a hand-built model, only where a hazard exists", "[graph][barriers]") {
    // An imported texture (StorageRead before and after the frame):
    //   p0 storage read, p1 storage read   : no barrier (same layout, no write)
    //   p2 sampled read                    : one (layout change)
    //   p3 storage read, p4 sampled read   : one each (layout changes)
    //   p5 storage write                   : one (write after reads)
    //   frame end                          : one (StorageWrite -> StorageRead)
    GraphModel m;
    m.resources = {textureDecl("color", ResourceOrigin::Imported, 2)};
    for (int i = 0; i < 5; ++i)
        m.resources.push_back(textureDecl("o" + std::to_string(i), ResourceOrigin::Imported, 2));
    auto sampled = [](uint32_t r) { return accessDecl("src", r, 0, Access::SampledRead); };
    m.passes = {passDecl("p0", {readOf(0, 0), writeOf(1, 0)}), passDecl("p1", {readOf(0, 0), writeOf(2, 0)}),
                passDecl("p2", {sampled(0), writeOf(3, 0)}),   passDecl("p3", {readOf(0, 0), writeOf(4, 0)}),
                passDecl("p4", {sampled(0), writeOf(5, 0)}),   passDecl("p5", {writeOf(0, 0)})};
    for (uint32_t r = 1; r < m.resources.size(); ++r) m.resources[r].initialState = ResourceState::Undefined;
    REQUIRE_NOTHROW(validate(m));
    const auto o = order(m, allAlive(m));
    REQUIRE(o == std::vector<uint32_t>{0, 1, 2, 3, 4, 5});
    const auto plan = planBarriers(m, o, std::vector<bool>(m.resources.size(), false));
    CHECK(barriersOn(plan.beforePass[0], 0) == 0);
    CHECK(barriersOn(plan.beforePass[1], 0) == 0);
    CHECK(barriersOn(plan.beforePass[2], 0) == 1);
    CHECK(barriersOn(plan.beforePass[3], 0) == 1);
    CHECK(barriersOn(plan.beforePass[4], 0) == 1);
    REQUIRE(barriersOn(plan.beforePass[5], 0) == 1);
    CHECK(plan.beforePass[5].front().before == ResourceState::SampledRead);
    CHECK(plan.beforePass[5].front().after == ResourceState::StorageWrite);
    // Each o_i: Undefined -> StorageWrite before its pass, then to its final StorageRead.
    for (uint32_t pos = 0; pos < 5; ++pos) CHECK(barriersOn(plan.beforePass[pos], pos + 1) == 1);
    CHECK(plan.frameEnd.size() == 1 + 5);
    CHECK(plan.count() == 3 + 1 + 5 + 6);
    CHECK(plan.endState[0] == ResourceState::StorageRead);
}

TEST_CASE("barriers: a texture that is only read needs none at all", "[graph][barriers]") {
    GraphModel m;
    m.resources = {textureDecl("lut", ResourceOrigin::Imported, 1), textureDecl("a", ResourceOrigin::Transient, 2),
                   textureDecl("b", ResourceOrigin::Transient, 2)};
    m.resources[1].output = m.resources[2].output = true;
    m.passes = {passDecl("pa", {readOf(0, 0), writeOf(1, 0)}), passDecl("pb", {readOf(0, 0), writeOf(2, 0)})};
    const auto plan = planBarriers(m, order(m, allAlive(m)), {false, false, false});
    for (const auto& list : plan.beforePass) CHECK(barriersOn(list, 0) == 0);
    CHECK(barriersOn(plan.frameEnd, 0) == 0);
    // Each output: one discarding barrier before its write, nothing more.
    CHECK(plan.count() == 2);

    // A transient sharing memory with another starts with an aliasing barrier.
    const auto aliased = planBarriers(m, order(m, allAlive(m)), {false, true, false});
    REQUIRE(barriersOn(aliased.beforePass[0], 1) == 1);
    CHECK(aliased.beforePass[0].front().aliased);
    CHECK(aliased.beforePass[0].front().discard);
}
