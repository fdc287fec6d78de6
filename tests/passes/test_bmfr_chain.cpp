// The BMFR chain (docs/passes/bmfr-chain.md): its passes and the one reprojection
// decision both accumulations read; the chain written node by node in a chain file
// reproduces it bit for bit; the preset form applies its settings; bad settings fail.
// Quality against the reference: tests/passes/test_chain_quality.cpp; NaN/Inf,
// extremes and odd sizes: tests/passes/test_chain_robustness.cpp.
#include <catch2/catch.hpp>

#include <algorithm>

#include <hush/passes/bmfr/chain.hpp>
#include <hush/passes/chain_file.hpp>
#include <hush/passes/chain_runner.hpp>
#include <hush/core/error.hpp>

#include "chain_test_util.hpp"
#include "support/gpu_context.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

constexpr const char* kBmfrByNodes = R"({
  "name": "bmfr-by-nodes",
  "nodes": [
    {"id": "surface", "node": "surface",
     "inputs": {"normal": "input.normal", "depth": "input.depth", "meshid": "input.meshid"}},
    {"id": "reproject", "node": "reproject", "inputs": {"motion": "input.motion", "surface": "surface"}},
    {"id": "demod", "node": "demodulate",
     "inputs": {"radiance": "input.color", "albedo": "input.albedo", "emission": "input.emission"}},
    {"id": "acc", "node": "bmfr.accumulate", "inputs": {"current": "demod", "reprojection": "reproject"}},
    {"id": "fit", "node": "bmfr.fit",
     "inputs": {"illumination": "acc", "normal": "input.normal", "position": "input.position"}},
    // the same decision as the first accumulation (Sec. 3.3)
    {"id": "post", "node": "bmfr.accumulate", "inputs": {"current": "fit", "reprojection": "reproject"},
     "settings": {"minWeight": 0.1}},
    {"id": "remod", "node": "remodulate",
     "inputs": {"a": "post", "albedo": "input.albedo", "emission": "input.emission"}},
    {"id": "tm", "node": "tonemap", "inputs": {"radiance": "remod"}},
    {"id": "taa", "node": "taa", "inputs": {"color": "tm", "motion": "input.motion", "reprojection": "reproject"}}
  ],
  "outputs": {"display": "taa", "radiance": "remod"}
})";

std::string errorOf(const std::string& json) {
    auto error = test::errorFrom([&] { passes::parseChainJson(json, "chain.json"); });
    return error ? std::string(error->what()) : std::string("(no error)");
}

} // namespace

TEST_CASE("bmfr chain: its stages, and one reprojection decision read by both accumulations", "[bmfr][bmfr-chain]") {
    test::ValidationScope scope;
    passes::ChainRunner runner(test::gpu().device, std::make_unique<passes::BmfrChain>(), {40, 24});
    const auto& model = runner.graph().model();
    auto passIndex = [&](const std::string& name) {
        for (uint32_t p = 0; p < model.passes.size(); ++p)
            if (model.passes[p].name == name) return int(p);
        return -1;
    };
    for (const char* name : {"bmfr.surface", "bmfr.reproject", "bmfr.demodulate", "bmfr.accumulate", "bmfr.fit",
                             "bmfr.post_accumulate", "bmfr.remodulate", "bmfr.tonemap", "bmfr.taa"}) {
        INFO(name);
        CHECK(passIndex(name) >= 0);
    }
    // The order of Fig. 2: accumulate < fit < post-accumulate.
    CHECK(passIndex("bmfr.accumulate") < passIndex("bmfr.fit"));
    CHECK(passIndex("bmfr.fit") < passIndex("bmfr.post_accumulate"));
    // Both accumulations sample the resource the reprojection pass wrote, and there is one.
    auto reprojectionReads = [&](const std::string& pass) {
        std::vector<std::string> names;
        for (const auto& access : model.passes[size_t(passIndex(pass))].accesses)
            if (access.resource != graph::kNone) names.push_back(model.resources[access.resource].name);
        return std::count(names.begin(), names.end(), "bmfr.reproject");
    };
    CHECK(reprojectionReads("bmfr.accumulate") == 1);
    CHECK(reprojectionReads("bmfr.post_accumulate") == 1);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("a chain file written node by node reproduces the built-in bmfr chain", "[bmfr][bmfr-chain][chain-file]") {
    test::ValidationScope scope;
    auto chain = passes::parseChainJson(kBmfrByNodes, "bmfr.json");
    CHECK(chain->name() == "bmfr-by-nodes");
    CHECK(chain->inputs() == passes::BmfrChain().inputs());
    const std::vector<tracer::Frame> frames(cornellSequence().begin(), cornellSequence().begin() + 4);
    const auto fromFile = runSequence(std::move(chain), frames);
    const auto builtin = runSequence(std::make_unique<passes::BmfrChain>(), frames);
    for (size_t f = 0; f < frames.size(); ++f) {
        INFO("frame " << f);
        CHECK(nonFinite(builtin[f]) == 0);
        CHECK(relativeL1(fromFile[f], builtin[f]) == 0.0);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("a chain file based on bmfr applies its settings", "[bmfr][bmfr-chain][chain-file]") {
    test::ValidationScope scope;
    auto same = passes::parseChainJson(R"({"base": "bmfr"})", "a.json");
    auto other = passes::parseChainJson(R"({"base": "bmfr", "settings": {
        "accumulate": {"minWeight": 0.5}, "postAccumulate": {"minWeight": 0.25},
        "fit": {"blockSize": 16, "epsilon": 0.02, "offsetBlocks": false,
                "features": ["one", "normalX", "normalY", "normalZ", "positionX", "positionY", "positionZ", "roughness"]},
        "useTaa": false}})", "b.json");
    CHECK(other->name() == "b");
    auto* bmfr = dynamic_cast<const passes::BmfrChain*>(&passes::unwrapChain(*other));
    REQUIRE(bmfr);
    CHECK(bmfr->settings().accumulate.minWeight == 0.5f);
    CHECK(bmfr->settings().postAccumulate.minWeight == 0.25f);
    CHECK(bmfr->settings().fit.blockSize == 16);
    CHECK(bmfr->settings().fit.epsilon == 0.02f);
    CHECK(!bmfr->settings().fit.offsetBlocks);
    REQUIRE(bmfr->settings().fit.features.size() == 8);
    CHECK(bmfr->settings().fit.features.back() == passes::BmfrFeature::Roughness);
    CHECK(!bmfr->settings().back.useTaa);
    // The roughness feature makes roughness an input.
    const auto inputs = other->inputs();
    CHECK(std::find(inputs.begin(), inputs.end(), passes::InputChannel::Roughness) != inputs.end());
    // The defaults are the paper's (Sec. 3.1, 3.2, 3.3, 6.1).
    const passes::BmfrSettings d;
    CHECK(d.accumulate.minWeight == 0.2f);
    CHECK(d.postAccumulate.minWeight == 0.1f);
    CHECK(d.fit.blockSize == 0);   // follows the frame (docs/sweep.md)
    CHECK(d.fit.epsilon == 0.01f);
    CHECK(d.fit.features.size() == 10);
    CHECK(d.fit.offsetBlocks);
    CHECK(d.back.useTaa);

    const std::vector<tracer::Frame> frames(cornellSequence().begin(), cornellSequence().begin() + 2);
    const auto a = runSequence(std::move(same), frames);
    const auto builtin = runSequence(std::make_unique<passes::BmfrChain>(), frames);
    CHECK(relativeL1(a.back(), builtin.back()) == 0.0);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("bmfr chain settings errors name the field", "[bmfr][bmfr-chain][chain-file]") {
    using Catch::Contains;
    CHECK_THAT(errorOf(R"({"base": "bmfr", "settings": {"accumulate": {"minWeight": 0}}})"),
               Contains("settings.accumulate.minWeight"));
    CHECK_THAT(errorOf(R"({"base": "bmfr", "settings": {"fit": {"blockSize": 24}}})"),
               Contains("settings.fit.blockSize") && Contains("0, 8, 16, 32 or 64"));
    CHECK_THAT(errorOf(R"({"base": "bmfr", "settings": {"fit": {"features": ["one", "nx"]}}})"),
               Contains("settings.fit.features[1]") && Contains("unknown value 'nx'") && Contains("'normalX'"));
    CHECK_THAT(errorOf(R"({"base": "bmfr", "settings": {"fit": {"features": []}}})"),
               Contains("settings.fit.features"));
    CHECK_THAT(errorOf(R"({"base": "bmfr", "settings": {"post": {}}})"),
               Contains("settings: unknown field 'post'") && Contains("postAccumulate"));
    REQUIRE_THROWS_AS(passes::BmfrChain({.accumulate = {.minWeight = 0.0f}}), Error);
    CHECK(passes::makeBuiltinChain("bmfr")->name() == "bmfr");
}
