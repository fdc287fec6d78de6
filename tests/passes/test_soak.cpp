// The soak run (samples/soak) at test size: every built-in chain for 300 frames,
// with a camera cut and a size change every 34 (three sizes, each three times). The
// RHI's live objects and the device memory hush holds must be exactly the same at
// the end of every segment of one size, outputs stay finite, and the process's
// resident memory must not grow from a size's second segment to its third by more
// than a margin for the allocator's own caches (the first also warms the driver's
// shader cache).
// hush-bench-soak runs the same for 10,000 frames (docs/reliability.md).
#include <catch2/catch.hpp>

#include "soak.hpp"
#include "support/gpu_context.hpp"

using namespace hush;

TEST_CASE("soak: 300 frames with cuts and size changes hold no more objects or memory at the end", "[soak][gpu]") {
    for (const char* chain : {"eaw", "svgf", "bmfr", "mara", "rdae"}) {
        DYNAMIC_SECTION(chain) {
            test::ValidationScope validation;
            soak::SoakPlan plan;
            plan.chain = chain;
            plan.frames = 300;
            plan.segmentFrames = 34;
            plan.sizes = {{32, 32}, {24, 20}, {32, 16}};
            plan.sequenceFrames = 4;
            const auto result = soak::runSoak(test::gpu().device, plan);
            REQUIRE(result.samples.size() == 9);
            for (size_t i = 0; i + 3 < result.samples.size(); ++i) {
                const auto& first = result.samples[i];
                const auto& again = result.samples[i + 3];
                INFO("segments " << i << " and " << i + 3 << " at " << first.size.width << "x" << first.size.height);
                CHECK(again.liveObjects == first.liveObjects);
                CHECK(again.deviceBytes == first.deviceBytes);
                // Resident memory keeps rising for the first ten or so runners (the
                // driver's and the validation layer's caches, glibc's arenas), then stays
                // flat (hush-bench-soak, docs/reliability.md): a margin of 16 MiB. Leaks
                // of GPU objects are caught exactly by the two checks above.
                if (i >= 3) CHECK(again.residentBytes <= first.residentBytes + 16u * 1024 * 1024);
            }
            for (const auto& s : result.samples) CHECK(s.nonFinite == 0);
            CHECK(result.liveObjectsPer1000 == 0.0);
            CHECK(result.deviceBytesPer1000 == 0.0);
            HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
        }
    }
}
