// Timestamps: a timed compute pass has a positive duration, and consecutive passes'
// ticks are ordered. No timed assertion beyond "> 0": speed is for benchmarks.
#include <catch2/catch.hpp>

#include "support/gpu_context.hpp"

using namespace hush::rhi;
using namespace hush::test;

namespace {

constexpr uint32_t kSize = 64;

struct Busy {
    ComputePipeline pipeline = computePipeline("timestamps/busy", "busy");
    Buffer out = gpu().device.createBuffer(
        {.label = "busy out", .size = kSize * kSize * 4, .usage = BufferUsage::Storage | BufferUsage::CopySrc});
    BindGroup group = gpu().device.createBindGroup(
        {.label = "busy", .layout = pipeline.getBindGroupLayout(0), .entries = {{.binding = 0, .buffer = out}}});

    void pass(CommandEncoder& encoder, const QuerySet& set, uint32_t begin, uint32_t end) {
        auto p = encoder.beginComputePass({.label = "busy", .timestampWrites = {set, begin, end}});
        p.setPipeline(pipeline);
        p.setBindGroup(0, group);
        const uint32_t params[2] = {kSize, 64};
        p.setPushConstants(params, sizeof(params));
        p.dispatchThreads(kSize, kSize);
        p.end();
    }
};

} // namespace

TEST_CASE("timestamps: the adapter has timestamps with a known period", "[timestamps][gpu]") {
    ValidationScope validation;
    const auto& limits = gpu().device.adapterInfo().limits;
    CHECK(limits.timestampsSupported);   // lavapipe has them; the rest of this file needs them
    CHECK(limits.timestampPeriodNs > 0.0);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("timestamps: a timed compute pass takes a positive time", "[timestamps][gpu]") {
    ValidationScope validation;
    Busy busy;
    auto queries = gpu().device.createQuerySet({.label = "one pass", .count = 2});
    CHECK(queries.count() == 2);
    CHECK(queries.label() == "one pass");
    submitAndWait([&](CommandEncoder& encoder) {
        encoder.bufferBarrier({{busy.out, ResourceState::Undefined, ResourceState::StorageWrite}});
        busy.pass(encoder, queries, 0, 1);
    });
    const auto ticks = queries.readTicks(0, 2);
    REQUIRE(ticks.size() == 2);
    CHECK(ticks[0] < ticks[1]);
    const double ms = queries.elapsedMs(0, 1);
    CHECK(ms > 0.0);
    // elapsedMs is the tick difference scaled by the period (1e-9 relative for rounding).
    const double fromTicks = double(ticks[1] - ticks[0]) * gpu().device.adapterInfo().limits.timestampPeriodNs * 1e-6;
    CHECK(ms == Approx(fromTicks).epsilon(1e-9));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("timestamps: two consecutive passes are ordered", "[timestamps][gpu]") {
    ValidationScope validation;
    Busy busy;
    auto queries = gpu().device.createQuerySet({.label = "two passes", .count = 4});
    // Run twice: query sets are reusable (each write resets its query first).
    for (int round = 0; round < 2; ++round) {
        INFO("round " << round);
        submitAndWait([&](CommandEncoder& encoder) {
            encoder.bufferBarrier({{busy.out, round == 0 ? ResourceState::Undefined : ResourceState::StorageWrite,
                                    ResourceState::StorageWrite}});
            busy.pass(encoder, queries, 0, 1);
            encoder.bufferBarrier({{busy.out, ResourceState::StorageWrite, ResourceState::StorageWrite}});
            busy.pass(encoder, queries, 2, 3);
        });
        const auto t = queries.readTicks(0, 4);
        REQUIRE(t.size() == 4);
        CHECK(t[0] <= t[1]);
        CHECK(t[1] <= t[2]);
        CHECK(t[2] <= t[3]);
        CHECK(queries.elapsedMs(0, 1) > 0.0);
        CHECK(queries.elapsedMs(2, 3) > 0.0);
        CHECK(queries.elapsedMs(0, 3) >= queries.elapsedMs(0, 1) + queries.elapsedMs(2, 3) - 1e-9);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("timestamps: encoder writeTimestamp brackets work outside passes", "[timestamps][gpu]") {
    ValidationScope validation;
    Busy busy;
    auto queries = gpu().device.createQuerySet({.label = "manual", .count = 2});
    submitAndWait([&](CommandEncoder& encoder) {
        encoder.bufferBarrier({{busy.out, ResourceState::Undefined, ResourceState::StorageWrite}});
        encoder.resetQuerySet(queries, 0, 2);
        encoder.writeTimestamp(queries, 0);
        auto p = encoder.beginComputePass({.label = "untimed"});
        p.setPipeline(busy.pipeline);
        p.setBindGroup(0, busy.group);
        const uint32_t params[2] = {kSize, 64};
        p.setPushConstants(params, sizeof(params));
        p.dispatchThreads(kSize, kSize);
        p.end();
        encoder.writeTimestamp(queries, 1);
    });
    CHECK(queries.elapsedMs(0, 1) > 0.0);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("timestamps: reading a query that was never written throws", "[timestamps][errors][gpu]") {
    ValidationScope validation;
    auto queries = gpu().device.createQuerySet({.label = "unwritten", .count = 2});
    const auto error = errorFrom([&] { queries.readTicks(0, 2); });
    REQUIRE(error);
    CHECK_THAT(error->what(), Catch::Matchers::Contains("unwritten"));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
