#pragma once
// CPU reference of bmfr/accumulate, written from Koskela et al. 2019 Sec. 3.1 and 3.3
// and the node header: a cumulative moving average until the new sample's weight
// would fall below minWeight, then exponential; the sample count travels in alpha.
#include <hush/passes/bmfr/accumulate.hpp>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// One frame: rgb accumulated, alpha the sample count. `previous` is last frame's
// output (ignored where historyValid is false or the decision says disoccluded).
FloatImage bmfrAccumulate(const FloatImage& input, const FloatImage& decision, const FloatImage& previous,
                          const passes::BmfrAccumulateSettings& settings, bool historyValid);

} // namespace hush::passes_test::reference
