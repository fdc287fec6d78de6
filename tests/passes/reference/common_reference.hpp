#pragma once
// CPU references of passes/common: written from the formulas in the node headers
// and ALGORITHMS.md, independently of the shaders.
#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// radiance / factor(albedo), factor as in passes/common/demodulate.hpp. rgb + alpha 1.
FloatImage demodulate(const FloatImage& radiance, const FloatImage& albedo, float eps);
// (a + b) * factor(albedo); b may be empty.
FloatImage remodulate(const FloatImage& a, const FloatImage* b, const FloatImage& albedo, float eps);
// Non-finite -> replacement, then clamp; returns the pixels with any non-finite component.
FloatImage sanitize(const FloatImage& in, float lo, float hi, float replacement, size_t& replacedPixels);

} // namespace hush::passes_test::reference

namespace hush::passes_test::reference {
// passes/common/surface: normalDepth (4 channels) and gradientMesh (4 channels).
struct SurfaceImages {
    FloatImage normalDepth, gradientMesh;
};
SurfaceImages surface(const FloatImage& normal, const FloatImage& depth, const FloatImage& meshId);
} // namespace hush::passes_test::reference
