// Compile step 3, order: topological over read-after-write, write-after-read and
// write-after-write, ties broken by declaration order; and step 4a, lifetimes, which
// are positions in that order.
#include <catch2/catch.hpp>

#include <hush/graph/compile_steps.hpp>

#include "graph/graph_test_util.hpp"
#include "graph/model_builders.hpp"

using namespace hush;
using namespace hush::graph;
using namespace hush::graph_test;
using hush::test::gpu;
using hush::test::ValidationScope;
using Order = std::vector<uint32_t>;
using Names = std::vector<std::string>;

TEST_CASE("order: independent passes keep their declaration order", "[graph][order]") {
    GraphModel m;
    for (uint32_t i = 0; i < 5; ++i) {
        m.resources.push_back(textureDecl("out" + std::to_string(i), ResourceOrigin::Imported, 2));
        m.passes.push_back(passDecl("p" + std::to_string(i), {writeOf(i, 0)}));
    }
    CHECK(order(m, allAlive(m)) == Order{0, 1, 2, 3, 4});
}

TEST_CASE("order: a reader declared before its producer runs after it (read after write)", "[graph][order]") {
    GraphModel m;
    m.resources = {textureDecl("x", ResourceOrigin::Transient, 2), textureDecl("y", ResourceOrigin::Transient, 2),
                   textureDecl("z", ResourceOrigin::Imported, 2)};
    m.resources[1].output = true;
    m.passes = {passDecl("consumer", {readOf(0, 1), writeOf(1, 0)}), passDecl("independent", {writeOf(2, 0)}),
                passDecl("producer", {writeOf(0, 0)})};
    REQUIRE_NOTHROW(validate(m));
    // Ready at the start: independent (1) and producer (2), in declaration order.
    CHECK(order(m, allAlive(m)) == Order{1, 2, 0});
}

TEST_CASE("order: a reader of the old version runs before the writer (write after read)", "[graph][order]") {
    GraphModel m;
    m.resources = {textureDecl("color", ResourceOrigin::Imported, 2),
                   textureDecl("copy", ResourceOrigin::Transient, 2)};
    m.resources[1].output = true;
    m.passes = {passDecl("overwrite", {accessDecl("color", 0, 0, Access::StorageReadWrite)}),
                passDecl("snapshot", {readOf(0, 0, "color"), writeOf(1, 0)})};
    REQUIRE_NOTHROW(validate(m));
    CHECK(order(m, allAlive(m)) == Order{1, 0});
}

TEST_CASE("order: chained writes run in version order (write after write)", "[graph][order]") {
    GraphModel m;
    m.resources = {textureDecl("accum", ResourceOrigin::Imported, 4)};
    m.passes = {passDecl("third", {accessDecl("dst", 0, 2, Access::StorageReadWrite)}),
                passDecl("second", {accessDecl("dst", 0, 1, Access::StorageReadWrite)}),
                passDecl("first", {writeOf(0, 0)})};
    REQUIRE_NOTHROW(validate(m));
    CHECK(order(m, allAlive(m)) == Order{2, 1, 0});
}

TEST_CASE("order: ties go to the pass declared first, at every step", "[graph][order]") {
    // p1 needs p3; p0, p2 and p3 are free. Kahn's algorithm with a min-queue:
    // p0, p2, p3 (declaration order among the ready), then p1 once p3 has run, then p4.
    GraphModel m;
    m.resources = {textureDecl("r3", ResourceOrigin::Transient, 2)};
    for (uint32_t i = 0; i < 5; ++i)
        m.resources.push_back(textureDecl("o" + std::to_string(i), ResourceOrigin::Imported, 2));
    m.passes = {passDecl("p0", {writeOf(1, 0)}), passDecl("p1", {readOf(0, 1), writeOf(2, 0)}),
                passDecl("p2", {writeOf(3, 0)}), passDecl("p3", {writeOf(0, 0)}),
                passDecl("p4", {readOf(0, 1), writeOf(5, 0)})};
    REQUIRE_NOTHROW(validate(m));
    CHECK(order(m, allAlive(m)) == Order{0, 2, 3, 1, 4});

    // Culled passes are left out of the order; the rest keep their relative order.
    auto c = allAlive(m);
    c.passAlive[2] = false;
    CHECK(order(m, c) == Order{0, 3, 1, 4});
    CHECK(order(m, cull(m)) == Order{0, 2, 3, 1, 4});
}

TEST_CASE("order: lifetimes are first and last positions in the order", "[graph][order]") {
    GraphModel m;
    m.resources = {textureDecl("in", ResourceOrigin::Imported, 1), textureDecl("a", ResourceOrigin::Transient, 2),
                   textureDecl("b", ResourceOrigin::Transient, 2), textureDecl("c", ResourceOrigin::Transient, 2),
                   textureDecl("never", ResourceOrigin::Transient, 1)};
    m.resources[2].output = true;
    m.passes = {passDecl("pa", {readOf(0, 0), writeOf(1, 0)}),   // position 0
                passDecl("pc", {readOf(1, 1), writeOf(3, 0)}),   // position 1
                passDecl("pb", {readOf(3, 1), writeOf(2, 0)}),   // position 2
                passDecl("last", {readOf(1, 1)}, true)};         // position 3, reads a again
    const auto o = order(m, allAlive(m));
    REQUIRE(o == Order{0, 1, 2, 3});
    const auto life = lifetimes(m, o);
    REQUIRE(life.size() == 5);
    CHECK((life[0].first == 0 && life[0].last == 0));
    CHECK((life[1].first == 0 && life[1].last == 3));   // a: written first, read last
    CHECK((life[3].first == 1 && life[3].last == 2));
    CHECK((life[2].first == 2 && life[2].last == 3));   // b is an output: it lives to the frame's end
    CHECK_FALSE(life[4].used());
}

TEST_CASE("order: a graph runs its passes in dependency order, stable otherwise", "[graph][order][gpu]") {
    ValidationScope validation;
    const auto p = makePipelines();
    constexpr uint32_t kW = 48, kH = 32;
    auto target = makeTexture("target", kW, kH);
    upload(target, fillImage(50, kW, kH), ResourceState::Undefined, ResourceState::StorageRead);

    RenderGraph g(gpu().device, {.label = "order"});
    g.setOutputSize({kW, kH});
    const auto t0 = g.importTexture(
        "target", target, {.initialState = ResourceState::StorageRead, .finalState = ResourceState::StorageRead});
    const auto a = addFill(g, p, "a", 1);
    const auto b = addFill(g, p, "b", 2);
    const auto snapshot = addCopy(g, p, "snapshot", t0, 0);   // reads the target before it is overwritten
    const auto c = addCombine(g, p, "c", a, b, {3, 5, 7, 1});
    addCopyInto(g, p, "overwrite", c, t0, 0);   // writes the target
    const auto d = addCombine(g, p, "d", snapshot, c, {9, 11, 13, 2});
    g.markOutput(d);
    g.execute();
    g.waitIdle();
    CHECK(g.passOrder() == Names{"a", "b", "snapshot", "c", "overwrite", "d"});

    // d = f(old target, c): the snapshot saw the target before the overwrite.
    const auto old = fillImage(50, kW, kH), va = fillImage(1, kW, kH), vb = fillImage(2, kW, kH);
    std::vector<uint32_t> vc(old.size()), vd(old.size());
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            const size_t i = size_t(y) * kW + x;
            vc[i] = combineReference(va[i], vb[i], {3, 5, 7, 1}, x, y);
            vd[i] = combineReference(old[i], vc[i], {9, 11, 13, 2}, x, y);
        }
    CHECK(readOutput(g, d) == vd);
    CHECK(download(target, ResourceState::StorageRead) == vc);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
