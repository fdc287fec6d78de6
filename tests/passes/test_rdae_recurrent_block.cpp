// The RCNN block against the CPU over frames: frame 0 sees a zero hidden state, later
// frames last frame's output, and after resetHistory() the state is zero again.
#include <catch2/catch.hpp>

#include <hush/passes/rdae/recurrent_block.hpp>

#include "rdae_test_util.hpp"
#include "reference/rdae_conv.hpp"

using namespace hush;
using namespace hush::passes_test;

TEST_CASE("rdae recurrent block carries its state across frames, and a reset clears it",
          "[rdae][rdae-recurrent-block]") {
    test::ValidationScope scope;
    const uint32_t w = 13, h = 9, c = 6;
    const passes::RdaeTensorFormat f{.levels = 0, .format = rhi::Format::RGBA32Float};
    const auto pIn = randomConv("rcnn.input", c, c, 1), pMix = randomConv("rcnn.mix", 2 * c, c, 2),
               pOut = randomConv("rcnn.output", c, c, 3);
    const auto& device = test::gpu().device;
    const auto wIn = passes::uploadRdaeConv(device, pIn, c), wMix = passes::uploadRdaeConv(device, pMix, c),
               wOut = passes::uploadRdaeConv(device, pOut, c);
    NodeHarness harness({w, h});
    auto x = randomTensor(c, w, h, -1.0f, 1.0f, 10);
    const auto input = importTensor(harness, "x", x, 0, f);
    const auto out = passes::addRdaeRecurrentBlock(harness.ctx, "rcnn", input, {&wIn, &wMix, &wOut}, f);

    Tensor hidden(c, w, h);   // zero
    auto cpuStep = [&](const Tensor& in) {
        const auto a = reference::rdaeConv(in, nullptr, pIn, true);
        hidden = reference::rdaeConv(reference::rdaeConv(a, &hidden, pMix, true), nullptr, pOut, true);
        return hidden;
    };
    std::vector<Tensor> gpuFrames;
    for (int frame = 0; frame < 3; ++frame) {
        INFO("frame " << frame);
        x = randomTensor(c, w, h, -1.0f, 1.0f, 20 + frame);
        harness.update("x", packTensor(x));
        gpuFrames.push_back(runTensor(harness, out, w, h));
        HUSH_REQUIRE_TENSORS_MATCH(gpuFrames.back(), cpuStep(x), 1e-5f, 1e-4f);
    }
    // The state matters: frame 2 differs from what the block gives without history.
    harness.graph.resetHistory();
    hidden = Tensor(c, w, h);
    const auto afterReset = runTensor(harness, out, w, h);
    HUSH_REQUIRE_TENSORS_MATCH(afterReset, cpuStep(x), 1e-5f, 1e-4f);
    CHECK(!compareTensors(afterReset, gpuFrames[2], 1e-3f, 0.0f).empty());
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
