#pragma once
// CPU reference of the edge-avoiding a-trous filter of Dammertz et al. 2010 (the
// EAW baseline), in double precision, written from the paper's formulas and the
// guards stated in passes/include/hush/passes/eaw/atrous.hpp, independently of the
// shader.
#include <vector>

#include <hush/passes/eaw/atrous.hpp>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// 4 channels: rgb filtered, alpha the centre's. color and position: >= 3 channels,
// normal: >= 3 channels.
// With `depth` (1 channel, linear), positions compare relative to the centre's depth
// against sigmaXRelative.
FloatImage eawAtrousLevel(const FloatImage& color, const FloatImage& normal, const FloatImage& position,
                          uint32_t level, const passes::EawSettings& s = {}, const FloatImage* depth = nullptr);

// Every level's output, level i filtering level i-1's.
std::vector<FloatImage> eawAtrousLevels(const FloatImage& color, const FloatImage& normal,
                                        const FloatImage& position, const passes::EawSettings& s = {});

} // namespace hush::passes_test::reference
