// Compile step 4b, memory aliasing: planAliasing on hand-made items, and a 20-pass
// chain whose transients share memory, checked against the CPU. Each pass reads two
// earlier results, so lifetimes overlap in uneven ways; were any lifetime too short,
// a later pass would overwrite a texture that is still to be read, and the exact
// integer result would differ.
#include <catch2/catch.hpp>

#include <algorithm>

#include <hush/graph/compile_steps.hpp>

#include "graph/graph_test_util.hpp"

using namespace hush;
using namespace hush::graph;
using namespace hush::graph_test;
using hush::test::gpu;
using hush::test::Lcg;
using hush::test::ValidationScope;

namespace {

uint64_t alignUp(uint64_t v, uint64_t a) { return (v + a - 1) / a * a; }
bool livesOverlap(const Lifetime& a, const Lifetime& b) { return a.first <= b.last && b.first <= a.last; }

// Everything planAliasing promises, checked for one problem.
void checkPlan(const std::vector<AliasItem>& items, const AliasPlan& plan) {
    REQUIRE(plan.offsets.size() == items.size());
    REQUIRE(plan.slots.size() == items.size());
    uint64_t unaliased = 0, end = 0, stacked = 0;
    for (size_t i = 0; i < items.size(); ++i) {
        INFO("item " << i);
        CHECK(plan.offsets[i] % items[i].alignment == 0);
        unaliased += alignUp(items[i].size, items[i].alignment);
        stacked += items[i].size + items[i].alignment - 1;
        end = std::max(end, plan.offsets[i] + items[i].size);
        for (size_t j = 0; j < items.size(); ++j) {
            if (j == i) continue;
            if (plan.slots[j] == plan.slots[i]) CHECK(plan.offsets[j] == plan.offsets[i]);
            if (!livesOverlap(items[i].lifetime, items[j].lifetime)) continue;
            INFO("item " << j << " is alive at the same time");
            const bool disjoint = plan.offsets[i] + items[i].size <= plan.offsets[j] ||
                                  plan.offsets[j] + items[j].size <= plan.offsets[i];
            CHECK(disjoint);
        }
    }
    CHECK(plan.blockBytes == end);
    CHECK(plan.unaliasedBytes == unaliased);
    // Never worse than stacking every item, each padded to its alignment. (It can exceed
    // unaliasedBytes when alignments differ: separate allocations each start aligned.)
    CHECK(plan.blockBytes <= stacked);
}

AliasItem item(uint64_t size, uint64_t alignment, uint32_t first, uint32_t last) {
    return {size, alignment, {first, last}};
}

} // namespace

TEST_CASE("aliasing: items with disjoint lifetimes reuse the same memory", "[graph][aliasing]") {
    const std::vector<AliasItem> items = {item(4096, 256, 0, 0), item(4096, 256, 1, 1), item(4096, 256, 2, 3)};
    const auto plan = planAliasing(items);
    checkPlan(items, plan);
    CHECK(plan.offsets == std::vector<uint64_t>{0, 0, 0});
    CHECK(plan.slots[0] == plan.slots[1]);
    CHECK(plan.slots[1] == plan.slots[2]);
    CHECK(plan.blockBytes == 4096);
    CHECK(plan.unaliasedBytes == 3 * 4096);
}

TEST_CASE("aliasing: items alive at the same time never share bytes", "[graph][aliasing]") {
    // [0,1] and [1,2] touch at position 1: both alive there.
    const std::vector<AliasItem> items = {item(1000, 256, 0, 1), item(1000, 256, 1, 2), item(500, 64, 0, 2)};
    const auto plan = planAliasing(items);
    checkPlan(items, plan);
    CHECK(plan.blockBytes >= 2000 + 500);
    CHECK(plan.unaliasedBytes == 1024 + 1024 + 512);
    CHECK(plan.blockBytes <= plan.unaliasedBytes);
}

TEST_CASE("aliasing: a small item fills the gap a large one's lifetime leaves", "[graph][aliasing]") {
    // Big A lives [0,1], big B [2,3]: they share offset 0. Small C [0,3] sits above.
    // Small D [2,2] can reuse nothing of A's while B holds it, so it goes beside C.
    const std::vector<AliasItem> items = {item(8192, 1024, 0, 1), item(8192, 1024, 2, 3), item(1024, 1024, 0, 3),
                                          item(1024, 1024, 2, 2)};
    const auto plan = planAliasing(items);
    checkPlan(items, plan);
    CHECK(plan.offsets[0] == 0);
    CHECK(plan.offsets[1] == 0);
    CHECK(plan.blockBytes == 8192 + 2 * 1024);
    CHECK(plan.unaliasedBytes == 2 * 8192 + 2 * 1024);
}

TEST_CASE("aliasing: nothing to place", "[graph][aliasing]") {
    const auto plan = planAliasing({});
    CHECK(plan.offsets.empty());
    CHECK(plan.blockBytes == 0);
    CHECK(plan.unaliasedBytes == 0);
}

TEST_CASE("aliasing: random problems keep every promise", "[graph][aliasing]") {
    Lcg rng(2024);
    for (int problem = 0; problem < 300; ++problem) {
        const uint32_t count = 1 + rng.next() % 24, positions = 1 + rng.next() % 12;
        std::vector<AliasItem> items;
        for (uint32_t i = 0; i < count; ++i) {
            const uint32_t a = rng.next() % positions, b = rng.next() % positions;
            const uint64_t alignment = uint64_t(1) << (rng.next() % 13);
            // Half the problems with sizes that are multiples of the alignment, as image requirements are.
            uint64_t size = 1 + rng.next() % 100000;
            if (problem % 2) size = alignUp(size, alignment);
            items.push_back(item(size, alignment, std::min(a, b), std::max(a, b)));
        }
        INFO("problem " << problem);
        checkPlan(items, planAliasing(items));
    }
}

namespace {

struct ChainResult {
    std::vector<std::vector<uint32_t>> frames;   // the chain's output, per frame
    MemoryReport memory;
};

constexpr uint32_t kPasses = 20;
constexpr uint32_t kW = 64, kH = 48;

CombineParams paramsOf(uint32_t i) { return {2 * i + 3, 0x9E3779B1u + 2 * i, i * 0x01234567u, 1 + i % 7}; }
// Pass i reads result i - 1 and result i - 1 - gap(i) (the imported input when < 0).
int secondInput(uint32_t i) { return int(i) - 1 - int((i * 5) % 4); }

// Frame f runs on input fillImage(1000 + f).
ChainResult runChain(bool aliasing, uint32_t frames) {
    const auto p = makePipelines();
    auto input = makeTexture("chain input", kW, kH);
    RenderGraph g(gpu().device, {.label = aliasing ? "chain.aliased" : "chain.separate", .aliasing = aliasing});
    g.setOutputSize({kW, kH});
    const auto in = g.importTexture(
        "input", input, {.initialState = ResourceState::StorageRead, .finalState = ResourceState::StorageRead});
    std::vector<TextureHandle> results;
    for (uint32_t i = 0; i < kPasses; ++i) {
        const auto a = i == 0 ? in : results[i - 1];
        const auto b = secondInput(i) < 0 ? in : results[size_t(secondInput(i))];
        results.push_back(addCombine(g, p, "step." + std::to_string(i), a, b, paramsOf(i)));
    }
    g.markOutput(results.back());

    ChainResult out;
    auto before = ResourceState::Undefined;
    for (uint32_t f = 0; f < frames; ++f) {
        upload(input, fillImage(1000 + f, kW, kH), before, ResourceState::StorageRead);
        before = ResourceState::StorageRead;
        g.execute();
        g.waitIdle();
        out.frames.push_back(readOutput(g, results.back()));
    }
    CHECK(g.culledPasses().empty());
    CHECK(g.passOrder().size() == kPasses);
    out.memory = g.memory();
    return out;
}

std::vector<uint32_t> chainReference(uint32_t frame) {
    const auto input = fillImage(1000 + frame, kW, kH);
    std::vector<std::vector<uint32_t>> results;
    for (uint32_t i = 0; i < kPasses; ++i) {
        const auto& a = i == 0 ? input : results[i - 1];
        const auto& b = secondInput(i) < 0 ? input : results[size_t(secondInput(i))];
        std::vector<uint32_t> r(input.size());
        for (uint32_t y = 0; y < kH; ++y)
            for (uint32_t x = 0; x < kW; ++x) {
                const size_t k = size_t(y) * kW + x;
                r[k] = combineReference(a[k], b[k], paramsOf(i), x, y);
            }
        results.push_back(std::move(r));
    }
    return results.back();
}

} // namespace

TEST_CASE("aliasing: a 20-pass chain of aliased transients matches the CPU", "[graph][aliasing][gpu]") {
    ValidationScope validation;
    constexpr uint32_t kFrames = 3;
    const auto aliased = runChain(true, kFrames);
    for (uint32_t f = 0; f < kFrames; ++f) {
        INFO("frame " << f);
        const auto expected = chainReference(f);
        const auto& got = aliased.frames[f];
        REQUIRE(got.size() == expected.size());
        size_t wrong = 0, first = got.size();
        for (size_t k = 0; k < got.size(); ++k)
            if (got[k] != expected[k]) {
                ++wrong;
                first = std::min(first, k);
            }
        INFO(wrong << " texels differ, the first at (" << first % kW << ", " << first / kW << ")");
        CHECK(wrong == 0);
    }
    // Aliasing happened: 19 aliasable transients (the output is never aliased) fit in
    // much less than 19 textures' worth, since at most 5 are alive at once.
    const auto& m = aliased.memory;
    CHECK(m.transientTextures == kPasses);
    CHECK(m.transientAliasedBytes < m.transientUnaliasedBytes);
    CHECK(m.transientAliasedBytes * 2 < m.transientUnaliasedBytes);
    CHECK(m.outputBytes == uint64_t(kW) * kH * 4);
    CHECK(m.historyBytes == 0);

    // Without aliasing: the same results, and each transient in memory of its own.
    const auto separate = runChain(false, kFrames);
    CHECK(separate.frames == aliased.frames);
    CHECK(separate.memory.transientAliasedBytes == separate.memory.transientUnaliasedBytes);
    CHECK(separate.memory.transientUnaliasedBytes == m.transientUnaliasedBytes);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
