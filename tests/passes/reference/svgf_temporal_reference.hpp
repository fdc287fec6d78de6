#pragma once
// CPU references of svgf/temporal_accumulation and svgf/variance_estimate, written
// from Schied et al. 2017 Sec. 4.1, 4.2, 4.4 and the node headers.
#include <hush/passes/svgf/temporal_accumulation.hpp>
#include <hush/passes/svgf/variance_estimate.hpp>

#include "reference/common_reference.hpp"

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

// rgb illumination, a variance.
FloatImage svgfVariance(const SvgfTemporalImages& temporal, const SurfaceImages& surface,
                        const passes::SvgfVarianceSettings& settings);

// Rec. 709 luminance.
float luminance(float r, float g, float b);

} // namespace hush::passes_test::reference
