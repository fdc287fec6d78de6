#pragma once
// CPU reference of passes/common/taa, written from the formulas in its header
// (Karis 2014; Salvi 2016; Keys 1981) and the decision encoding of reproject.hpp, in
// double precision, independently of the shader.
#include <hush/passes/common/taa.hpp>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// TAA frame after frame: holds its history (last output) like the graph does.
class Taa {
public:
    explicit Taa(const passes::TaaSettings& settings) : settings_(settings) {}
    // One frame: `current` (>= 3 channels), `motion` (>= 2 channels, pixels) and,
    // if not empty, a reprojection decision (4 channels, reproject.hpp's encoding);
    // returns rgb + alpha 1, which becomes the history of the next frame.
    FloatImage frame(const FloatImage& current, const FloatImage& motion, const FloatImage& decision = {});
    // As RenderGraph::resetHistory(): the next frame has no history.
    void reset() { hasHistory_ = false; }

private:
    passes::TaaSettings settings_;
    FloatImage history_;
    bool hasHistory_ = false;
};

} // namespace hush::passes_test::reference
