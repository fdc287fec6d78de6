#pragma once
// CPU reference of Mara et al. 2017 stage 6 (seed 000 Sec. 3.4): the 3x3 median of
// each channel, edge pixels repeated, by sorting (std::nth_element), not a network.
#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

FloatImage maraMedian(const FloatImage& color);

} // namespace hush::passes_test::reference
