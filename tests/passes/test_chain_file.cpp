// Chain files (docs/passes/chain-files.md): valid files build chains that match the
// built-in ones; invalid ones fail with errors naming the file, the JSON path and
// the problem.
#include <catch2/catch.hpp>

#include <hush/passes/chain_file.hpp>
#include <hush/passes/eaw/chain.hpp>
#include <hush/passes/svgf/chain.hpp>

#include "chain_test_util.hpp"
#include "support/gpu_context.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

// EAW written out node by node: must reproduce EawChain exactly.
constexpr const char* kEawByNodes = R"({
  // comments are allowed
  "name": "eaw-by-nodes",
  "nodes": [
    {"id": "demod", "node": "demodulate",
     "inputs": {"radiance": "input.color", "albedo": "input.albedo", "emission": "input.emission"}},
    {"id": "filter", "node": "eaw.atrous",
     "inputs": {"color": "demod", "normal": "input.normal", "position": "input.position", "depth": "input.depth"}},
    {"id": "remod", "node": "remodulate",
     "inputs": {"a": "filter.filtered", "albedo": "input.albedo", "emission": "input.emission"}},
    {"id": "tm", "node": "tonemap", "inputs": {"radiance": "remod"}}
  ],
  "outputs": {"display": "tm", "radiance": "remod"}
})";

std::string errorOf(const std::string& json) {
    auto error = test::errorFrom([&] { passes::parseChainJson(json, "chain.json"); });
    return error ? std::string(error->what()) : std::string("(no error)");
}

} // namespace

TEST_CASE("a chain file written node by node reproduces the built-in eaw chain", "[chain][chain-file]") {
    test::ValidationScope scope;
    auto chain = passes::parseChainJson(kEawByNodes, "eaw.json");
    CHECK(chain->name() == "eaw-by-nodes");
    const auto inputs = chain->inputs();
    CHECK(inputs == passes::EawChain().inputs());
    const std::vector<tracer::Frame> frames(cornellSequence().begin(), cornellSequence().begin() + 2);
    const auto fromFile = runSequence(std::move(chain), frames);
    const auto builtin = runSequence(std::make_unique<passes::EawChain>(), frames);
    CHECK(relativeL1(fromFile.back(), builtin.back()) == 0.0);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("a chain file based on svgf applies its settings", "[chain][chain-file]") {
    test::ValidationScope scope;
    auto same = passes::parseChainJson(R"({"base": "svgf"})", "a.json");
    auto fewer = passes::parseChainJson(R"({"base": "svgf", "settings": {"atrous": {"iterations": 2}}})", "b.json");
    CHECK(fewer->name() == "b");   // the file's stem: two presets of svgf stay apart in reports
    auto* svgf = dynamic_cast<const passes::SvgfChain*>(&passes::unwrapChain(*fewer));
    REQUIRE(svgf);
    CHECK(svgf->settings().atrous.iterations == 2);
    const std::vector<tracer::Frame> frames(cornellSequence().begin(), cornellSequence().begin() + 2);
    const auto a = runSequence(std::move(same), frames);
    const auto builtin = runSequence(std::make_unique<passes::SvgfChain>(), frames);
    CHECK(relativeL1(a.back(), builtin.back()) == 0.0);
    const auto b = runSequence(std::move(fewer), frames);
    CHECK(relativeL1(b.back(), builtin.back()) > 0.0);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("an svgf chain written node by node reproduces SvgfChain on one lighting term", "[chain][chain-file]") {
    test::ValidationScope scope;
    auto chain = passes::parseChainJson(R"({
      "nodes": [
        {"id": "surface", "node": "surface",
         "inputs": {"normal": "input.normal", "depth": "input.depth", "meshid": "input.meshid"}},
        {"id": "reproject", "node": "reproject", "inputs": {"motion": "input.motion", "surface": "surface"}},
        {"id": "demod", "node": "demodulate", "inputs": {"radiance": "input.color", "albedo": "input.albedo"}},
        {"id": "temporal", "node": "svgf.temporal",
         "inputs": {"illumination": "demod", "reprojection": "reproject", "color_history": "history:atrous.level0"}},
        {"id": "variance", "node": "svgf.variance", "inputs": {"temporal": "temporal", "surface": "surface"}},
        {"id": "atrous", "node": "svgf.atrous", "inputs": {"illum_variance": "variance", "surface": "surface"}},
        {"id": "remod", "node": "remodulate", "inputs": {"a": "atrous", "albedo": "input.albedo"}},
        {"id": "tm", "node": "tonemap", "inputs": {"radiance": "remod"}},
        {"id": "taa", "node": "taa", "inputs": {"color": "tm", "motion": "input.motion", "reprojection": "reproject"}}
      ],
      "outputs": {"display": "taa", "radiance": "remod"}
    })", "svgf-nodes.json");
    const std::vector<tracer::Frame> frames(cornellSequence().begin(), cornellSequence().begin() + 3);
    const auto out = runSequence(std::move(chain), frames);
    CHECK(nonFinite(out.back()) == 0);
    // The same stages as SvgfChain filtering the colour as one term, emission not separated.
    passes::SvgfSettings oneTerm;
    oneTerm.front.separateEmission = false;
    oneTerm.splitLighting = false;
    const auto builtin = runSequence(std::make_unique<passes::SvgfChain>(oneTerm), frames);
    for (size_t f = 0; f < frames.size(); ++f) {
        INFO("frame " << f);
        CHECK(relativeL1(out[f], builtin[f]) == 0.0);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("chain file errors name the file, the field and the problem", "[chain][chain-file]") {
    using Catch::Contains;
    CHECK_THAT(errorOf(R"({"base": "svgf", "settings": {"atrous": {"iterashuns": 2}}})"),
               Contains("chain.json: settings.atrous: unknown field 'iterashuns'") && Contains("iterations"));
    CHECK_THAT(errorOf(R"({"base": "svgf", "settings": {"atrous": {"iterations": -1}}})"),
               Contains("settings.atrous.iterations") && Contains("integer"));
    CHECK_THAT(errorOf(R"({"base": "bmfr9"})"), Contains("unknown chain 'bmfr9'"));
    CHECK_THAT(errorOf(R"({"nodes": [{"id": "a", "node": "blur"}], "outputs": {"display": "a"}})"),
               Contains("nodes[0].node: unknown node type 'blur'") && Contains("svgf.atrous"));
    CHECK_THAT(errorOf(R"({"nodes": [{"id": "t", "node": "tonemap", "inputs": {"radiance": "input.colour"}}],
                          "outputs": {"display": "t"}})"),
               Contains("nodes[0].inputs.radiance") && Contains("'input.colour' names no input channel"));
    CHECK_THAT(errorOf(R"({"nodes": [{"id": "t", "node": "tonemap", "inputs": {"radiance": "later"}},
                                     {"id": "later", "node": "tonemap", "inputs": {"radiance": "input.color"}}],
                          "outputs": {"display": "t"}})"),
               Contains("defined after this one"));
    CHECK_THAT(errorOf(R"({"nodes": [{"id": "t", "node": "tonemap", "inputs": {"radiance": "input.color", "hdr": "x"}}],
                          "outputs": {"display": "t"}})"),
               Contains("nodes[0].inputs: unknown field 'hdr'") && Contains("radiance"));
    CHECK_THAT(errorOf(R"({"nodes": [{"id": "t", "node": "tonemap"}], "outputs": {"display": "t"}})"),
               Contains("input 'radiance' of node 't' (tonemap) is not connected"));
    CHECK_THAT(errorOf(R"({"nodes": [{"id": "s", "node": "surface", "inputs": {"normal": "input.normal",
                          "depth": "input.depth", "meshid": "input.meshid"}},
                          {"id": "t", "node": "tonemap", "inputs": {"radiance": "s"}}], "outputs": {"display": "t"}})"),
               Contains("nodes[1].inputs.radiance") && Contains("takes a texture"));
    CHECK_THAT(errorOf(R"({"nodes": [{"id": "t", "node": "tonemap", "inputs": {"radiance": "input.color"}}],
                          "outputs": {"display": "t.colour"}})"),
               Contains("has no output 'colour'"));
    CHECK_THAT(errorOf(R"({"nodes": [{"id": "t", "node": "tonemap", "inputs": {"radiance": "input.color"}}]})"),
               Contains("missing 'outputs'"));
    CHECK_THAT(errorOf("{\n  \"base\": \"svgf\",\n  \"settings\": {\n}"), Contains("chain.json:4:"));
    CHECK_THAT(errorOf(R"({"nodes": [{"id": "a", "node": "tonemap", "inputs": {"radiance": "input.color"}},
                                     {"id": "a", "node": "tonemap", "inputs": {"radiance": "input.color"}}],
                          "outputs": {"display": "a"}})"),
               Contains("nodes[1].id: 'a' is already used"));
    CHECK_THAT(errorOf(R"({"nodes": [{"id": "d", "node": "demodulate", "inputs": {"radiance": "input.color", "albedo": "input.albedo"}},
                                     {"id": "t", "node": "svgf.temporal",
                                      "inputs": {"illumination": "d", "reprojection": "d", "color_history": "history:nope"}}],
                          "outputs": {"display": "d"}})"),
               Contains("nodes[1].inputs.color_history: 'nope' refers to no node called 'nope'"));
    CHECK_THAT(errorOf(R"({"nodes": [{"id": "s", "node": "surface",
                                      "inputs": {"normal": "input.normal", "depth": "input.depth", "meshid": "input.meshid"}},
                                     {"id": "t", "node": "tonemap", "inputs": {"radiance": "history:s"}}],
                          "outputs": {"display": "t"}})"),
               Contains("nodes[1].inputs.radiance: 'history:s': only a node's texture output has a history"));
    CHECK_THAT(errorOf(R"({"nodes": [{"id": "t", "node": "tonemap", "inputs": {"radiance": "later"}},
                                     {"id": "later", "node": "tonemap", "inputs": {"radiance": "input.color"}}],
                          "outputs": {"display": "t"}})"),
               Contains("defined after this one") && Contains("\"history:later\""));
    auto missing = test::errorFrom([] { passes::makeChain("no/such/chain.json"); });
    REQUIRE(missing);
    CHECK_THAT(missing->what(), Contains("'no/such/chain.json' is neither a built-in chain"));
}

TEST_CASE("a chain's name is a plain folder name: no separators, no leading dot", "[chain][chain-file]") {
    using Catch::Contains;
    for (const char* good : {"svgf", "my-chain_2", "eaw.fewer", "A1"}) CHECK(passes::isValidChainName(good));
    for (const char* bad : {"", "..", ".hidden", "../x", "/abs", "a/b", "a\\b", "sp ace", "t\ab"})
        CHECK_FALSE(passes::isValidChainName(bad));
    CHECK_FALSE(passes::isValidChainName(std::string(65, 'a')));
    CHECK_THAT(errorOf(R"({"name": "../x", "base": "svgf"})"),
               Contains("chain.json: name: '../x' is not a valid chain name"));
    CHECK_THAT(errorOf(R"({"name": "/tmp/x", "nodes": [{"id": "t", "node": "tonemap", "inputs": {"radiance": "input.color"}}],
                          "outputs": {"display": "t"}})"),
               Contains("name: '/tmp/x' is not a valid chain name"));
}
