#pragma once
// CPU reference of svgf/variance_estimate, written from Schied et al. 2017 Sec. 4.2,
// 4.4 and the node header.
#include <hush/passes/svgf/variance_estimate.hpp>

#include "pass_test_util.hpp"
#include "reference/common_surface.hpp"
#include "reference/svgf_temporal_accumulation.hpp"

namespace hush::passes_test::reference {

// rgb illumination, a variance.
FloatImage svgfVariance(const SvgfTemporalImages& temporal, const SurfaceImages& surface,
                        const passes::SvgfVarianceSettings& settings);

} // namespace hush::passes_test::reference
