// The results file of `hush-bench-chains --quick` (tests/bench/bench_chains.sh runs
// it): every chain at every size timed, every pass with its bytes and its fraction of
// the same run's roofline, finite figures, no non-finite output, and a quality score
// per scene and chain. Hidden ("[.]"): it reads a file the script made, named by
// HUSH_BENCH_OUTPUT; the chains it must hold are HUSH_BENCH_CHAINS (comma-separated).
// Times are only checked to be positive and finite, never against a bound.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include <hush/core/arguments.hpp>
#include <hush/core/json.hpp>
#include <hush/core/read_file.hpp>

using hush::core::Json;

namespace {

std::string environment(const char* name) {
    const char* value = std::getenv(name);
    return value ? value : "";
}

bool finiteNumber(const Json& value) { return value.is_number() && std::isfinite(value.get<double>()); }

void checkPositiveTimes(const Json& times, const std::string& what) {
    INFO(what << ": " << times.dump());
    for (const char* key : {"median", "min", "max"}) {
        REQUIRE(finiteNumber(times.at(key)));
        CHECK(times.at(key).get<double>() > 0.0);
    }
    CHECK(times.at("min").get<double>() <= times.at("median").get<double>());
    CHECK(times.at("median").get<double>() <= times.at("max").get<double>());
}

void checkPass(const Json& pass, const std::string& chain) {
    const std::string name = pass.at("name").get<std::string>();
    INFO("pass " << name);
    CHECK(name.rfind(chain + ".", 0) == 0);
    REQUIRE(pass.at("listed_tiles").is_boolean());
    // A pass over listed tiles may have none to run (a still scene): no time, no roofline.
    if (pass.at("listed_tiles").get<bool>()) {
        CHECK(pass.at("gpu_ms").at("min").get<double>() >= 0.0);
        CHECK(pass.at("of_roofline").get<double>() == 0.0);
    } else {
        checkPositiveTimes(pass.at("gpu_ms"), name);
    }
    REQUIRE(finiteNumber(pass.at("of_roofline")));
    CHECK(pass.at("of_roofline").get<double>() >= 0.0);
    CHECK(pass.at("bytes_read").get<double>() >= 0.0);
    CHECK(pass.at("bytes_written").get<double>() >= 0.0);
}

void checkTiming(const Json& timing, const std::vector<std::string>& chains) {
    std::set<std::string> timed;
    for (const Json& entry : timing) {
        const std::string chain = entry.at("chain").get<std::string>();
        const std::string size = std::to_string(entry.at("width").get<int>()) + "x" +
                                 std::to_string(entry.at("height").get<int>());
        INFO(chain << " at " << size);
        timed.insert(chain + " " + size);
        checkPositiveTimes(entry.at("gpu_frame_ms"), "frame");
        REQUIRE(finiteNumber(entry.at("of_roofline")));
        CHECK(entry.at("of_roofline").get<double>() > 0.0);
        CHECK(entry.at("non_finite_output_values").get<double>() == 0.0);
        REQUIRE(entry.at("passes").size() > 0);
        for (const Json& pass : entry.at("passes")) checkPass(pass, chain);
    }
    for (const auto& chain : chains)
        for (const char* size : {"160x90", "320x180"}) {
            INFO("timing of " << chain << " at " << size);
            CHECK(timed.count(chain + " " + size) == 1);
        }
}

void checkRooflines(const Json& rooflines) {
    REQUIRE(rooflines.size() > 0);
    for (const Json& probe : rooflines) {
        INFO("roofline " << probe.dump());
        REQUIRE(finiteNumber(probe.at("gbps")));
        CHECK(probe.at("gbps").get<double>() > 0.0);
        CHECK(probe.at("verified").get<bool>());
    }
}

void checkQuality(const Json& quality, const std::vector<std::string>& chains) {
    REQUIRE(quality.at("scenes").size() > 0);
    for (const Json& scene : quality.at("scenes")) {
        std::set<std::string> scored;
        for (const Json& method : scene.at("methods")) {
            const std::string name = method.at("method").get<std::string>();
            INFO(scene.at("scene").get<std::string>() << ", " << name << ": " << method.dump());
            scored.insert(name);
            REQUIRE(finiteNumber(method.at("rmse")));
            CHECK(method.at("rmse").get<double>() >= 0.0);
            REQUIRE(finiteNumber(method.at("ssim")));
            CHECK(std::abs(method.at("ssim").get<double>()) <= 1.0);
            CHECK(method.at("non_finite_pixels").get<double>() == 0.0);
        }
        for (const auto& chain : chains) {
            INFO("quality of " << chain << " on " << scene.at("scene").get<std::string>());
            CHECK(scored.count(chain) == 1);
        }
    }
}

} // namespace

TEST_CASE("hush-bench-chains --quick writes a complete results file", "[.bench-chains-output]") {
    const std::string path = environment("HUSH_BENCH_OUTPUT");
    const auto chains = hush::core::splitList(environment("HUSH_BENCH_CHAINS"));
    REQUIRE_FALSE(path.empty());
    REQUIRE_FALSE(chains.empty());
    const Json results = hush::core::parseJson(hush::core::readFile(path, "results file"), path);
    checkRooflines(results.at("rooflines"));
    checkTiming(results.at("timing"), chains);
    checkQuality(results.at("quality"), chains);
}
