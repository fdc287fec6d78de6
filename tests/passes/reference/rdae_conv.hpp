#pragma once
// CPU reference of one RDAE convolution (Chaitanya et al. 2017 Eq. 1), in double:
// PyTorch's Conv2d(k=3, padding=1) over a concatenated with b, then leaky ReLU 0.1
// (or linear). Direct loops over the weights as PyTorch stores them ([O][I][3][3]),
// nothing of the GPU's packing.
#include <hush/passes/rdae/conv.hpp>

#include "rdae_test_util.hpp"

namespace hush::passes_test::reference {

Tensor rdaeConv(const Tensor& a, const Tensor* b, const passes::RdaeConvParameters& conv, bool leaky);

} // namespace hush::passes_test::reference
