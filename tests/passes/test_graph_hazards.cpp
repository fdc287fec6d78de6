// Every built-in chain's compiled graph replayed by an independent hazard check
// (hazard_check.hpp): no read-after-write, write-after-read or write-after-write
// between passes without a covering barrier, no access in the wrong state, aliased
// memory marked. And the check itself catches each kind of fault, made by editing
// a real graph's dump.
#include <catch2/catch.hpp>

#include <hush/passes/chain_file.hpp>
#include <hush/passes/chain_runner.hpp>

#include "chain_test_util.hpp"
#include "hazard_check.hpp"
#include "support/gpu_context.hpp"

using namespace hush;
using namespace hush::passes_test;
using Json = nlohmann::json;

namespace {

// The compiled graph of `chainJson` after one frame of the glossy scene at 64x64.
Json compiledGraph(const std::string& chainJson) {
    const auto& frames = sceneSequence("glossy", 64);
    passes::ChainRunner runner(test::gpu().device, passes::parseChainJson(chainJson, "test.json"), {64, 64});
    uploadFrame(runner, frames[0]);
    runner.run();
    return Json::parse(runner.graph().dumpJson());
}

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& l : lines) out += l + "\n";
    return out;
}

bool mentions(const std::vector<std::string>& problems, const std::string& part) {
    for (const auto& p : problems)
        if (p.find(part) != std::string::npos) return true;
    return false;
}

// The first live pass's barrier whose `before` and `after` match, as (pass, index).
std::pair<Json*, size_t> findBarrier(Json& dump, const std::string& before, const std::string& after, bool aliased) {
    for (Json& pass : dump["passes"]) {
        auto& barriers = pass["barriers"];
        for (size_t i = 0; i < barriers.size(); ++i)
            if (barriers[i]["before"] == before && barriers[i]["after"] == after && barriers[i]["aliased"] == aliased)
                return {&pass, i};
    }
    FAIL("no barrier " << before << " -> " << after);
    return {nullptr, 0};
}

} // namespace

TEST_CASE("graph hazards: every built-in chain's barriers cover every hazard", "[graph-hazards]") {
    test::ValidationScope scope;
    std::vector<std::string> chains;
    for (const auto& name : passes::builtinChainNames()) chains.push_back(R"({"base": ")" + name + R"("})");
    chains.push_back(R"({"name": "svgf-no-taa", "base": "svgf", "settings": {"useTaa": false}})");
    chains.push_back(R"({"name": "mara-matte", "base": "mara", "settings": {"glossy": "off"}})");
    for (const auto& chain : chains) {
        INFO(chain);
        const Json dump = compiledGraph(chain);
        const auto problems = findHazards(dump);
        std::printf("graph hazards: %s: %zu passes, %d barriers, %zu problems\n", chain.c_str(),
                    dump["passes"].size(), dump["barriersPerFrame"].get<int>(), problems.size());
        CHECK(joined(problems) == "");
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("graph hazards: the check finds a removed barrier, a wrong state and an unmarked alias",
          "[graph-hazards]") {
    const Json clean = compiledGraph(R"({"base": "svgf"})");
    REQUIRE(findHazards(clean).empty());

    SECTION("a read after a write without its barrier") {
        Json dump = clean;
        auto [pass, i] = findBarrier(dump, "storage-write", "sampled-read", false);
        const std::string resource = (*pass)["barriers"][i]["resource"];
        (*pass)["barriers"].erase(i);
        const auto problems = findHazards(dump);
        INFO(joined(problems));
        CHECK(mentions(problems, "reads " + resource + " after a write with no barrier between"));
    }
    SECTION("every barrier, removed alone, is missed") {
        // Each barrier the planner placed is needed: without it the replay finds a
        // hazard or a wrong state (a write after reads, across frames for a transient's
        // first use).
        size_t removed = 0;
        for (size_t p = 0; p < clean["passes"].size(); ++p)
            for (size_t b = 0; b < clean["passes"][p]["barriers"].size(); ++b) {
                Json dump = clean;
                const std::string what = dump["passes"][p]["name"].get<std::string>() + " / " +
                                         dump["passes"][p]["barriers"][b]["resource"].get<std::string>();
                dump["passes"][p]["barriers"].erase(b);
                INFO(what);
                CHECK_FALSE(findHazards(dump).empty());
                ++removed;
            }
        CHECK(removed == clean["barriersPerFrame"].get<size_t>() - clean["frameEndBarriers"].get<size_t>());
    }
    SECTION("an access in another state than the barrier left") {
        Json dump = clean;
        bool edited = false;
        for (Json& pass : dump["passes"])
            for (Json& a : pass["accesses"]) {
                const int64_t r = a["resource"];
                if (edited || r < 0 || a["access"] != "sampled-read" || pass["culled"].get<bool>()) continue;
                if (dump["resources"][size_t(r)]["origin"] != "transient") continue;
                a["access"] = "storage-read";
                edited = true;
            }
        REQUIRE(edited);
        const auto problems = findHazards(dump);
        INFO(joined(problems));
        CHECK(mentions(problems, "as 'storage-read' while it is in 'sampled-read'"));
    }
    SECTION("a barrier whose source state is not the resource's") {
        Json dump = clean;
        auto [pass, i] = findBarrier(dump, "storage-write", "sampled-read", false);
        (*pass)["barriers"][i]["before"] = "sampled-read";
        const auto problems = findHazards(dump);
        INFO(joined(problems));
        CHECK(mentions(problems, "from 'sampled-read', but the resource is in 'storage-write'"));
    }
    SECTION("aliased memory without the aliased mark") {
        Json dump = clean;
        for (Json& pass : dump["passes"])
            for (Json& b : pass["barriers"]) b["aliased"] = false;
        const auto problems = findHazards(dump);
        INFO(joined(problems));
        CHECK(mentions(problems, "but its first barrier is not marked aliased"));
    }
}
