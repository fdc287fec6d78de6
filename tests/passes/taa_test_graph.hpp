#pragma once
// One passes/common/taa node on a NodeHarness, fed frame by frame: the shared
// fixture of tests/passes/test_common_taa*.cpp.
#include <string>

#include <hush/passes/common/taa.hpp>

#include "pass_test_util.hpp"

namespace hush::passes_test {

struct TaaGraph {
    NodeHarness t;
    graph::TextureHandle out;
    bool withDecision;
    // withDecision: the node gets a reprojection decision input ("decision", rgba32f).
    TaaGraph(rhi::Extent2D size, const passes::TaaSettings& settings, bool withDecision_ = false)
        : t(size), withDecision(withDecision_) {
        const FloatImage blank(size.width, size.height, 4, 0.0f);
        const auto decision = withDecision ? t.input("decision", blank) : graph::TextureHandle{};
        out = passes::addTaaPass(t.ctx, "taa", t.input("current", blank),
                                 t.input("motion", FloatImage(size.width, size.height, 2, 0.0f), Format::RG32Float),
                                 settings, decision);
        t.graph.markOutput(out);
    }
    // Re-uploads the inputs and runs a frame; `decision` only with withDecision.
    FloatImage frame(const FloatImage& current, const FloatImage& motion, const FloatImage& decision = {}) {
        t.update("current", current);
        t.update("motion", motion);
        if (withDecision) t.update("decision", decision);
        t.graph.execute();
        t.graph.waitIdle();
        return readOutput(t.graph, out);
    }
};

inline FloatImage constantMotion(rhi::Extent2D size, float mx, float my) {
    return makeImage(size.width, size.height, 2, [&](uint32_t, uint32_t, uint32_t c) { return c == 0 ? mx : my; });
}

inline std::string describe(const passes::TaaSettings& s) {
    return "alpha " + std::to_string(s.alpha) + " box " + std::to_string(uint32_t(s.box)) + " rectify " +
           std::to_string(uint32_t(s.rectify)) + " gamma " + std::to_string(s.varianceGamma) + " filter " +
           (s.historyFilter == passes::TaaHistoryFilter::CatmullRom ? "catmull-rom" : "bilinear");
}

} // namespace hush::passes_test
