#pragma once
// CPU reference of the RDAE input tensor (shaders/rdae/input.glsl; docs/passes/rdae.md):
// illumination^0.2, the world normal rotated into view space (x, y), depth in metres
// as d / (1 + d), roughness clamped to [0, 1]; padded to a multiple of 2^levels by
// repeating the edge pixels. In double.
#include <array>

#include "rdae_test_util.hpp"

namespace hush::passes_test::reference {

Tensor rdaeInput(const FloatImage& illumination, const FloatImage& normal, const FloatImage& depth,
                 const FloatImage& roughness, const std::array<float, 16>& view, float metresPerUnit, uint32_t levels);

} // namespace hush::passes_test::reference
