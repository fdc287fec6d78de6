// The NaN contract for every accepted setting: each numeric, boolean and enum setting of
// every built-in chain, set alone to each end of its accepted range (or each of its
// values), either is refused with an error or gives finite outputs and histories on a
// short sequence. A setting whose accepted end made NaN (SVGF's luminanceEpsilon 0 did)
// fails here until its range or its shader is fixed.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <hush/core/error.hpp>
#include <hush/passes/bmfr/chain.hpp>
#include <hush/passes/chain_file.hpp>
#include <hush/passes/eaw/chain.hpp>
#include <hush/passes/mara/chain.hpp>
#include <hush/passes/rdae/chain.hpp>
#include <hush/passes/svgf/chain.hpp>

#include "chain_test_util.hpp"
#include "support/gpu_context.hpp"

using namespace hush;
using namespace hush::passes_test;
using Json = nlohmann::json;

namespace {

// One chain-file "settings" object per variation: a single field at one extreme.
struct Variation {
    std::string label;
    Json settings;
};

class Extremes {
public:
    Extremes(std::vector<Variation>& out, std::vector<std::string> path) : out_(out), path_(std::move(path)) {}

    void field(std::string_view key, float&, passes::Range r) { ends(key, r); }
    void field(std::string_view key, uint32_t&, passes::Range r) { ends(key, r); }
    void field(std::string_view key, int&, passes::Range r) { ends(key, r); }
    template <size_t N> void field(std::string_view key, uint32_t&, passes::Choices<N> c) {
        add(key, c.values[0]);
        add(key, c.values[N - 1]);
    }
    void field(std::string_view key, bool&) {
        add(key, false);
        add(key, true);
    }
    void field(std::string_view, std::string&) {}   // file names: not a numeric extreme
    template <class E, size_t N> void field(std::string_view key, E&, const passes::EnumNames<E, N>& names) {
        for (const auto& [name, value] : names) add(key, std::string(name));
    }
    template <class E, size_t N> void field(std::string_view, std::vector<E>&, const passes::EnumNames<E, N>&, size_t) {}
    template <class S> void section(std::string_view key, S& sub) {
        auto path = path_;
        path.emplace_back(key);
        describe(Extremes(out_, path), sub);
    }
    template <class S> void flatten(S& sub) { describe(*this, sub); }

private:
    void ends(std::string_view key, passes::Range r) {
        add(key, r.lo);
        add(key, r.hi);
    }
    template <class T> void add(std::string_view key, T value) {
        Json settings = Json::object();
        Json* at = &settings;
        std::string label;
        for (const auto& p : path_) {
            at = &(*at)[p];
            label += p + ".";
        }
        (*at)[std::string(key)] = value;
        out_.push_back({label + std::string(key) + " = " + Json(value).dump(), settings});
    }
    std::vector<Variation>& out_;
    std::vector<std::string> path_;
};

template <class S> std::vector<Variation> variationsOf() {
    std::vector<Variation> out;
    S s{};
    describe(Extremes(out, {}), s);
    return out;
}

// Runs 3 frames; returns "" or what went wrong.
std::string runVariation(const std::string& base, Json settings, const std::vector<tracer::Frame>& frames) {
    std::unique_ptr<passes::Chain> chain;
    try {
        chain = passes::parseChainJson(Json{{"base", base}, {"settings", settings}}.dump(), base + ".json");
        passes::ChainRunner runner(test::gpu().device, std::move(chain), {frames[0].width, frames[0].height});
        const auto histories = markHistorySources(runner.graph());
        for (size_t f = 0; f < 3; ++f) {
            uploadFrame(runner, frames[f]);
            runner.run();
        }
        if (nonFinite(runner.readDisplay())) return "non-finite display";
        if (nonFinite(runner.readRadiance())) return "non-finite radiance";
        for (const auto h : histories)
            if (nonFinite(runner.readTexture(h))) return "non-finite history";
    } catch (const Error& e) {
        // Refused with a clear error (a combination the chain cannot run): not accepted.
        if (e.kind() != ErrorKind::InvalidArgument && e.kind() != ErrorKind::Unsupported) throw;
    }
    return "";
}

void sweep(const std::string& base, std::vector<Variation> variations, const Json& fixed = Json::object()) {
    const auto& frames = sceneSequence("glossy", 32);
    size_t failures = 0;
    for (auto& v : variations) {
        v.settings.merge_patch(fixed);
        const std::string problem = runVariation(base, v.settings, frames);
        INFO(base << ": " << v.label);
        CHECK(problem == "");
        failures += !problem.empty();
    }
    std::printf("settings extremes: %s, %zu variations, %zu with non-finite values\n", base.c_str(), variations.size(),
                failures);
}

} // namespace

TEST_CASE("settings at the ends of their ranges keep outputs and histories finite: svgf", "[settings][extremes]") {
    test::ValidationScope scope;
    sweep("svgf", variationsOf<passes::SvgfSettings>());
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("settings at the ends of their ranges keep outputs and histories finite: eaw", "[settings][extremes]") {
    test::ValidationScope scope;
    sweep("eaw", variationsOf<passes::EawChainSettings>());
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("settings at the ends of their ranges keep outputs and histories finite: bmfr", "[settings][extremes]") {
    test::ValidationScope scope;
    sweep("bmfr", variationsOf<passes::BmfrSettings>());
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("settings at the ends of their ranges keep outputs and histories finite: mara", "[settings][extremes]") {
    test::ValidationScope scope;
    sweep("mara", variationsOf<passes::MaraSettings>());
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("settings at the ends of their ranges keep outputs and histories finite: rdae", "[settings][extremes]") {
    test::ValidationScope scope;
    // A small random network (the shipped weights fix width and levels).
    auto variations = variationsOf<passes::RdaeSettings>();
    std::erase_if(variations, [](const Variation& v) {
        return v.label.rfind("width", 0) == 0 || v.label.rfind("levels", 0) == 0;
    });
    sweep("rdae", variations,
          {{"width", 4}, {"levels", 2}, {"weights", std::string(HUSH_PASSES_TEST_DATA_DIR) + "/rdae_random_w4_l2.safetensors"}});
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
