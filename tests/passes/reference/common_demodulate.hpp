#pragma once
// CPU reference of passes/common/demodulate, written from the formula in the node
// header and ALGORITHMS.md, independently of the shader.
#include <cstdint>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// radiance / factor(albedo), factor as in passes/common/demodulate.hpp. rgb + alpha 1.
FloatImage demodulate(const FloatImage& radiance, const FloatImage& albedo, float eps);

// The per-channel factor at (x, y): max(albedo, eps), or 1 in every channel where the
// albedo is below eps in all three. Remodulation multiplies by the same factor.
void factor(const FloatImage& albedo, uint32_t x, uint32_t y, float eps, float out[3]);

} // namespace hush::passes_test::reference
