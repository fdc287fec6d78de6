#pragma once
// CPU reference of svgf/temporal_accumulation, written from Schied et al. 2017
// Sec. 4.1 and the node header. SvgfTemporalImages is its output, which
// svgf/variance_estimate's reference reads.
#include <hush/passes/svgf/temporal_accumulation.hpp>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

struct SvgfTemporalImages {
    FloatImage color;     // rgb integrated illumination, alpha 1
    FloatImage moments;   // mu1, mu2, history length, 0
};

// One frame of accumulation. `previous` is last frame's (colour history, moments
// history); ignored where historyValid is false.
SvgfTemporalImages svgfTemporal(const FloatImage& illumination, const FloatImage& decision,
                                const SvgfTemporalImages& previous, const passes::SvgfTemporalSettings& settings,
                                bool historyValid);

// Rec. 709 luminance.
float luminance(float r, float g, float b);

} // namespace hush::passes_test::reference
