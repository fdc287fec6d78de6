#pragma once
// CPU reference of RDAE 2x2 nearest upsampling: output (x, y) is input (x/2, y/2).
#include "rdae_test_util.hpp"

namespace hush::passes_test::reference {

Tensor rdaeUpsample(const Tensor& t);

} // namespace hush::passes_test::reference
