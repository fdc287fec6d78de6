#pragma once
// CPU reference of Mara et al. 2017 stage 5 (seed 000 Sec. 3.4), brute force: the
// minimum of c over the whole (2R+1) x (2R+1) box, not two 1D passes.
#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// `temporal`: c in channel 3. Returns the radius (1 channel, pixels).
FloatImage maraDisocclusion(const FloatImage& temporal, int boxRadius, double lowConfidence,
                            double lowConfidenceScale);

} // namespace hush::passes_test::reference
