#pragma once
// CPU reference of the BMFR fit (Koskela et al. 2019, Sec. 3.2), in double precision,
// written from the paper's formulas and the guards stated in
// passes/include/hush/passes/bmfr/fit.hpp and docs/passes/bmfr.md, independently of
// the shader. It uses the node's public block grid (bmfrBlockGrid, tested on its own)
// and draws the same noise N from the same documented hash.
#include <cstdint>

#include <hush/passes/bmfr/fit.hpp>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// illumination: >= 3 channels (a 4th is passed through, else alpha 1); normal and
// position: >= 3; albedo >= 3, roughness and meshId >= 1, only when a feature reads them.
struct BmfrImages {
    const FloatImage* illumination = nullptr;
    const FloatImage* normal = nullptr;
    const FloatImage* position = nullptr;
    const FloatImage* albedo = nullptr;
    const FloatImage* roughness = nullptr;
    const FloatImage* meshId = nullptr;
};

// The node's computation in double: the same scaled features, the same noise, a
// Householder QR of [T + N, z], back substitution with the same guards, T alpha with
// the noise-free T. rgba.
FloatImage bmfrFit(const BmfrImages& in, const passes::BmfrFitSettings& s, uint64_t frameIndex);

// The noise-free least-squares prediction per block: the orthogonal projection of z
// onto the span of the scaled noise-free T (what every least-squares solution,
// the minimum-norm one included, predicts), by Gram-Schmidt with re-orthogonalisation
// that drops columns dependent on the earlier ones. rgba.
FloatImage bmfrProjection(const BmfrImages& in, const passes::BmfrFitSettings& s, uint64_t frameIndex);

// The noise value the node adds to column `column` at `pixel` in frame `frame`.
float bmfrNoise(uint32_t x, uint32_t y, uint32_t frame, uint32_t column, float epsilon);

} // namespace hush::passes_test::reference
