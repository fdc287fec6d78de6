#pragma once
// CPU references of the display nodes (passes/common/tonemap, passes/common/taa),
// written from the formulas in their headers (Narkowicz 2016; Reinhard et al. 2002,
// Eq. 3; Karis 2014; Salvi 2016; Keys 1981) in double precision, independently of the shaders
// and of the public CPU tonemap functions.
#include <hush/passes/common/taa.hpp>
#include <hush/passes/common/tonemap.hpp>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// One linear HDR colour through the tonemap settings' operator.
void tonemapColor(const passes::TonemapSettings& settings, const double in[3], double out[3]);
// rgb tonemapped, alpha 1 (4 channels).
FloatImage tonemap(const FloatImage& radiance, const passes::TonemapSettings& settings);

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
