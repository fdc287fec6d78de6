#pragma once
// CPU reference of the RDAE output node: the first 3 channels cropped to the frame,
// clamped to [0, 9.2] (NaN to 0), raised to 5, at most 65504; alpha 1.
#include "rdae_test_util.hpp"

namespace hush::passes_test::reference {

FloatImage rdaeOutput(const Tensor& t, uint32_t width, uint32_t height);

} // namespace hush::passes_test::reference
