// passes/common/sanitize: NaN / Inf replaced and counted, ranges clamped.
#include <catch2/catch.hpp>

#include <tuple>

#include <cmath>
#include <limits>

#include <hush/passes/common/sanitize.hpp>
#include <hush/passes/frame_inputs.hpp>

#include "reference/common_sanitize.hpp"

using namespace hush;
using namespace hush::passes_test;
using passes::InputChannel;

TEST_CASE("sanitize replaces and counts non-finite values per channel", "[common][sanitize]") {
    test::ValidationScope scope;
    const uint32_t w = 13, h = 7;
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    auto color = randomImage(w, h, 3, 0.0f, 4.0f, 7);
    color.at(1, 1, 0) = nan;
    color.at(2, 1, 2) = inf;
    color.at(2, 1, 1) = -inf;   // same pixel: counted once
    color.at(5, 5, 0) = -3.0f;  // negative radiance: clamped, not counted
    color.at(8, 3, 0) = nan;    // two in one invocation's row of 4 (x 8..11): both counted
    color.at(9, 3, 1) = inf;
    auto depth = randomImage(w, h, 1, 0.5f, 9.0f, 8);
    depth.at(0, 6) = -inf;
    depth.at(12, 2) = nan;      // in the last, partial row of 4 (x 12..15 of 13)
    auto meshid = makeImage(w, h, 1, [](uint32_t x, uint32_t, uint32_t) { return float(x % 3); });
    meshid.at(4, 4) = nan;

    passes::FrameInputs frame(test::gpu().device, {w, h},
                              {InputChannel::Color, InputChannel::Depth, InputChannel::MeshId});
    frame.upload(InputChannel::Color, color.pixels, 3);
    frame.upload(InputChannel::Depth, depth.pixels, 1);
    frame.upload(InputChannel::MeshId, meshid.pixels, 1);

    passes::PipelineCache pipelines(test::gpu().device);
    graph::RenderGraph graph(test::gpu().device);
    graph.setOutputSize({w, h});
    passes::NodeContext ctx{graph, pipelines};
    auto out = passes::addSanitizePass(ctx, "sanitize", frame.import(graph));
    for (auto c : frame.channels()) graph.markOutput(out.inputs[c]);
    graph.execute();
    graph.waitIdle();

    auto counts = readOutputBuffer(graph, out.counts);
    REQUIRE(counts.size() == passes::kInputChannelCount);
    CHECK(counts[size_t(InputChannel::Color)] == 4);
    CHECK(counts[size_t(InputChannel::Depth)] == 2);
    CHECK(counts[size_t(InputChannel::MeshId)] == 1);
    CHECK(counts[size_t(InputChannel::Albedo)] == 0);

    struct Case {
        InputChannel channel;
        const FloatImage& image;
    };
    for (const Case& c : {Case{InputChannel::Color, color}, Case{InputChannel::Depth, depth},
                          Case{InputChannel::MeshId, meshid}}) {
        // The valid ranges of DESIGN.md's data conventions, written here rather than
        // read from passes::sanitizeRange, so that a change there fails this test.
        constexpr float big = std::numeric_limits<float>::max();
        const auto [lo, hi, replacement] = c.channel == InputChannel::Color   ? std::tuple{0.0f, 1e8f, 0.0f}
                                           : c.channel == InputChannel::Depth ? std::tuple{0.0f, big, 0.0f}
                                                                              : std::tuple{-1.0f, big, -1.0f};
        size_t replaced = 0;
        auto ref = reference::sanitize(c.image, lo, hi, replacement, replaced);
        auto gpu = readOutput(graph, out.inputs[c.channel]);
        INFO("channel " << passes::inputChannelInfo(c.channel).name);
        CHECK(replaced == counts[size_t(c.channel)]);
        HUSH_REQUIRE_IMAGES_MATCH(gpu, ref, 0.0f, 0.0f, c.image.channels);
    }
    CHECK(readOutput(graph, out.inputs[InputChannel::MeshId]).at(4, 4) == -1.0f);
    CHECK(readOutput(graph, out.inputs[InputChannel::Color]).at(5, 5, 0) == 0.0f);

    // The next frame starts counting from zero.
    graph.execute();
    graph.waitIdle();
    CHECK(readOutputBuffer(graph, out.counts)[size_t(InputChannel::Color)] == 4);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("frame inputs name the channel when the data is the wrong size", "[common][sanitize]") {
    passes::FrameInputs frame(test::gpu().device, {4, 4}, {InputChannel::Motion});
    std::vector<float> wrong(4 * 4 * 2 - 1);
    auto error = test::errorFrom([&] { frame.upload(InputChannel::Motion, wrong, 2); });
    REQUIRE(error);
    CHECK_THAT(error->what(), Catch::Contains("'motion'") && Catch::Contains("expected 32"));
    auto missing = test::errorFrom([&] { frame.upload(InputChannel::Depth, wrong, 1); });
    REQUIRE(missing);
    CHECK_THAT(missing->what(), Catch::Contains("'depth'"));
}
