// Indirect dispatches in the graph (PassBuilder::readIndirect, PassContext::
// dispatchIndirect): a pass writes workgroup counts, a later pass is dispatched by
// them, and the graph's barrier between the two makes the counts visible to the
// dispatch itself (synchronization validation checks it), frame after frame.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>

#include <hush/graph/compile_steps.hpp>

#include "graph/graph_test_util.hpp"

using namespace hush;
using namespace hush::graph;
using namespace hush::graph_test;
using hush::test::gpu;
using hush::test::ValidationScope;

namespace {

// counts = (x, y, z) -> tally dispatched by them; tally zeroed by the same shader.
struct IndirectGraph {
    rhi::ComputePipeline writeCounts = makePipeline(gpu().device, "write_counts");
    rhi::ComputePipeline tally = makePipeline(gpu().device, "tally_workgroups");
    RenderGraph g{gpu().device, {.label = "indirect"}};
    BufferHandle counts, result;
    uint32_t x = 0, y = 0, z = 0;

    BufferHandle addWrite(const std::string& name, const uint32_t* values) {
        struct Out {
            BufferHandle buffer;
        };
        return g.addPass<Out>(name, [&](PassBuilder& b, Out& o) {
            o.buffer = b.write("counts", b.create(name, BufferInfo{16}));
            const auto group = b.bindGroup(writeCounts);
            return [=, this](PassContext& pc) {
                rhi::PushConstants params(writeCounts);
                params.set("x", values[0]).set("y", values[1]).set("z", values[2]);
                pc.dispatch(writeCounts, group, {1, 1}, params);
            };
        }).buffer;
    }

    IndirectGraph() {
        g.setOutputSize({8, 8});
        static const uint32_t zero[3] = {0, 0, 0};
        counts = addWrite("counts", &x);
        const BufferHandle cleared = addWrite("tally", zero);
        struct Out {
            BufferHandle tally;
        };
        result = g.addPass<Out>("dispatched", [&](PassBuilder& b, Out& o) {
            const auto args = b.readIndirect("counts", counts);
            o.tally = b.readWrite("tally", cleared);
            const auto group = b.bindGroup(tally);
            return [=, this](PassContext& pc) { pc.dispatchIndirect(tally, group, args, rhi::PushConstants(tally)); };
        }).tally;
        g.markOutput(result);
    }

    std::vector<uint32_t> run(uint32_t gx, uint32_t gy, uint32_t gz) {
        x = gx, y = gy, z = gz;
        g.execute();
        g.waitIdle();
        return test::valuesOf<uint32_t>(gpu().queue().readBuffer(g.outputBuffer(result)));
    }
};

// tally_workgroups.comp's bit mask for every workgroup of a gx x gy x gz dispatch.
uint32_t workgroupBits(uint32_t gx, uint32_t gy, uint32_t gz) {
    uint32_t bits = 0;
    for (uint32_t k = 0; k < gz; ++k)
        for (uint32_t j = 0; j < gy; ++j)
            for (uint32_t i = 0; i < gx; ++i) bits |= 1u << (i + 4 * j + 16 * k);
    return bits;
}

} // namespace

TEST_CASE("indirect: a pass dispatched by counts an earlier pass wrote runs exactly those workgroups",
          "[graph][indirect][gpu]") {
    ValidationScope validation;
    IndirectGraph t;
    // (x, y, z) per frame; each workgroup is 4 x 2 invocations.
    const std::vector<std::array<uint32_t, 3>> frames = {{3, 2, 1}, {1, 1, 1}, {0, 1, 1}, {4, 4, 2}, {2, 3, 1}};
    for (const auto& [gx, gy, gz] : frames) {
        INFO(gx << " x " << gy << " x " << gz << " workgroups");
        const auto tally = t.run(gx, gy, gz);
        REQUIRE(tally.size() == 4);
        CHECK(tally[0] == gx * gy * gz * 8);
        CHECK(tally[1] == workgroupBits(gx, gy, gz));
        CHECK(tally[2] == (gx * gy * gz > 0 ? gx : 0u));
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("indirect: the counts reach the dispatch through one storage-write to indirect-read barrier",
          "[graph][indirect][gpu]") {
    ValidationScope validation;
    IndirectGraph t;
    t.run(1, 1, 1);
    const auto& m = t.g.model();
    const auto& dispatched = m.passes.back();
    REQUIRE(dispatched.name == "dispatched");
    const auto port = std::find_if(dispatched.accesses.begin(), dispatched.accesses.end(),
                                   [](const AccessDecl& a) { return a.port == "counts"; });
    REQUIRE(port != dispatched.accesses.end());
    CHECK(port->access == Access::IndirectRead);
    CHECK(std::string(toString(port->access)) == "indirect-read");

    const auto o = order(m, cull(m));
    const auto plan = planBarriers(m, o, std::vector<bool>(m.resources.size(), false));
    REQUIRE(plan.beforePass.size() == 3);
    REQUIRE(t.g.passOrder().back() == "dispatched");
    int found = 0;
    for (const auto& b : plan.beforePass[2]) {
        if (b.resource != t.counts.index) continue;
        ++found;
        CHECK(b.before == rhi::ResourceState::StorageWrite);
        CHECK(b.after == rhi::ResourceState::IndirectRead);
    }
    CHECK(found == 1);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
