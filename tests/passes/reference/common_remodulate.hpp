#pragma once
// CPU reference of passes/common/remodulate, written from the formula in the node
// header and ALGORITHMS.md, independently of the shader.
#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// (a + b) * factor(albedo); b may be empty. factor as in reference/common_demodulate.hpp.
FloatImage remodulate(const FloatImage& a, const FloatImage* b, const FloatImage& albedo, float eps);

} // namespace hush::passes_test::reference
