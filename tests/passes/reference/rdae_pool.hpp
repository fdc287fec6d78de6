#pragma once
// CPU reference of RDAE 2x2 max pooling: each output the largest of its 2x2 inputs.
#include "rdae_test_util.hpp"

namespace hush::passes_test::reference {

Tensor rdaePool(const Tensor& t);

} // namespace hush::passes_test::reference
