// Compile step 6, realize: the physical resources of a planned model, on a device.
// Imported resources are the application's; a history and its source share one
// ping-pong pair; transients with disjoint lifetimes share memory, outputs never do.
#include <catch2/catch.hpp>

#include "graph/graph_test_util.hpp"
#include "graph/model_builders.hpp"

using namespace hush;
using namespace hush::graph;
using namespace hush::graph_test;
using hush::test::gpu;

TEST_CASE("realize: imports, history pairs, aliasing and the memory report of a hand-built model",
          "[graph][realize][gpu]") {
    GraphModel m;
    m.outputSize = {32, 32};
    m.resources = {
        textureDecl("in", ResourceOrigin::Imported, 1),    // 0
        textureDecl("t1", ResourceOrigin::Transient, 2),   // 1: dies after pass 1
        textureDecl("t2", ResourceOrigin::Transient, 2),   // 2: dies after pass 2
        textureDecl("t3", ResourceOrigin::Transient, 2),   // 3: born after t1 died: may share its memory
        textureDecl("acc", ResourceOrigin::Transient, 2),  // 4: output, and the source of history 5
        textureDecl("acc", ResourceOrigin::History, 1),    // 5
    };
    m.resources[4].output = true;
    m.resources[5].historySource = 4;
    m.passes = {passDecl("p0", {readOf(0, 0), writeOf(1, 0)}), passDecl("p1", {readOf(1, 1), writeOf(2, 0)}),
                passDecl("p2", {readOf(2, 1), writeOf(3, 0)}),
                passDecl("p3", {readOf(3, 1), readOf(5, 0, "history"), writeOf(4, 0)})};
    validate(m);
    const auto culled = cull(m);
    const auto ordered = order(m, culled);
    const auto lives = lifetimes(m, ordered);
    const auto input = makeTexture("in", 32, 32);
    RealizeOptions options{.label = "realize", .aliasing = true, .importedTextures = {input, {}, {}, {}, {}, {}},
                           .importedBuffers = std::vector<rhi::Buffer>(6)};
    const auto r = realize(gpu().device, m, culled, ordered, lives, options);

    CHECK(r.textures[0][0].shared() == input.shared());   // the application's own texture
    // One pair, swapped: the history reads what the source wrote the frame before.
    REQUIRE(r.historyPair[4]);
    REQUIRE(r.historyPair[5]);
    CHECK(r.textures[5][0].shared() == r.textures[4][1].shared());
    CHECK(r.textures[5][1].shared() == r.textures[4][0].shared());
    CHECK(r.textures[4][0].shared() != r.textures[4][1].shared());
    CHECK(r.memory.historyBytes == 2 * r.textures[4][0].byteSize());
    // t1 and t3 never live at once: they share memory; t2 overlaps both.
    CHECK(r.memoryOffset[1] == r.memoryOffset[3]);
    CHECK(r.aliased[1]);
    CHECK(r.aliased[3]);
    CHECK(r.memoryOffset[2] != r.memoryOffset[1]);
    CHECK(r.memory.transientAliasedBytes < r.memory.transientUnaliasedBytes);
    CHECK(r.memory.transientTextures == 3);
    CHECK(r.extents[1] == rhi::Extent2D{32, 32});

    // Without aliasing every transient has its own memory.
    options.aliasing = false;
    const auto separate = realize(gpu().device, m, culled, ordered, lives, options);
    CHECK(separate.memory.transientAliasedBytes == separate.memory.transientUnaliasedBytes);
    CHECK_FALSE(separate.aliased[1]);
}
