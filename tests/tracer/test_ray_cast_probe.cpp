// The ray-casting probe (hush-bench-tracer's roofline) and the row pool it shares
// with the renderer. Its rates are times, so only their presence and the mix's
// arithmetic are asserted, never their size.
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <catch2/catch.hpp>

#include <hush/tracer/builtin_scenes.hpp>
#include <hush/tracer/ray_cast_probe.hpp>

#include "parallel_rows.hpp"

using namespace hush::tracer;

TEST_CASE("the ray-casting probe casts every kind of ray through a built-in scene", "[tracer][probe]") {
    const auto rates = probeRayCasting(makeBuiltinScene("cornell"), {.width = 32, .height = 24, .repeats = 1});
    for (double r : {rates.primary, rates.primaryPacket, rates.bounce, rates.shadow}) {
        CHECK(std::isfinite(r));
        CHECK(r > 0.0);
    }
}

TEST_CASE("the probe's roofline time adds each kind's rays at its own rate", "[tracer][probe]") {
    RayCastRates r;
    r.primary = 1.0, r.bounce = 2.0, r.shadow = 4.0;   // Mrays/s
    CHECK(r.secondsFor(1'000'000, 2'000'000, 2'000'000) == Approx(1.0 + 1.0 + 0.5));
    CHECK(r.secondsFor(0, 0, 4'000'000) == Approx(1.0));
    r.shadow = 0.0;
    CHECK(r.secondsFor(1'000'000, 0, 0) == Approx(1.0));   // an unmeasured kind not asked for
    CHECK(r.secondsFor(1'000'000, 0, 1) == 0.0);           // asked for: no roofline rather than a wrong one
}

TEST_CASE("the probe refuses sizes and repeat counts it cannot time", "[tracer][probe]") {
    const Scene scene = makeBuiltinScene("cornell");
    REQUIRE_THROWS_WITH(probeRayCasting(scene, {.width = 0, .height = 8}), Catch::Contains("ray-casting probe size 0x8"));
    REQUIRE_THROWS_WITH(probeRayCasting(scene, {.width = 8, .height = 8, .repeats = 0}),
                        Catch::Contains("repeats must be at least 1"));
}

TEST_CASE("parallelRows runs every row once and hands the first failure back", "[tracer]") {
    std::vector<std::atomic<int>> seen(97);
    detail::parallelRows(97, 3, [&](uint32_t y) { ++seen[y]; });
    for (const auto& s : seen) CHECK(s.load() == 1);
    REQUIRE_THROWS_WITH(detail::parallelRows(1000, 2,
                                             [&](uint32_t y) {
                                                 if (y == 5) throw std::runtime_error("row 5 failed");
                                             }),
                        "row 5 failed");
}
