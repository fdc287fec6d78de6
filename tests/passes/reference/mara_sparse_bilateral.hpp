#pragma once
// CPU reference of Mara et al. 2017's sparse cross-bilateral filter (seed 000 Sec. 3.4,
// stages 4 and 7), in double precision, from passes/include/hush/passes/mara/
// sparse_bilateral.hpp and shaders/mara/sparse_bilateral.comp's stated formulas
// (spiral taps, PCG rotation, Gaussian, plane and normal weights).
#include <cstdint>
#include <vector>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

struct MaraBilateralParams {
    uint32_t taps = 50;
    double spiralTurns = 7.0;
    double planeSigma = 0.02;
    double normalPower = 32.0;
};

// Jarzynski & Olano 2020's PCG hash, and the per-pixel, per-frame spiral rotation in
// [0, 1) (computed in float as the shader does: exactly reproducible).
uint32_t pcgHash(uint32_t v);
float maraSpiralRotation(uint32_t x, uint32_t y, uint32_t frame);

// The offset (pixels, before rounding) of tap i for radius r and a rotation.
void maraSpiralOffset(uint32_t i, const MaraBilateralParams& p, double radius, double rotation, double offset[2]);

struct MaraBilateralResult {
    FloatImage filtered;
    // Pixels one of whose taps lies within 2e-4 px of a rounding boundary: CPU and GPU
    // arithmetic (cos, sin in fp32) may round it to different pixels there.
    std::vector<bool> ambiguous;
};

// `radius`: a per-pixel radius map (1 channel), or nullptr for `fixedRadius`.
// normalDepth: normal xyz, depth; position: world xyz.
MaraBilateralResult maraSparseBilateral(const FloatImage& color, const FloatImage& normalDepth,
                                        const FloatImage& position, const FloatImage* radius, double fixedRadius,
                                        uint32_t frame, const MaraBilateralParams& params);

// The plane and normal weight of tap q for centre p (shared with the glossy blur).
double maraGeometryWeight(const FloatImage& normalDepth, const FloatImage& position, uint32_t px, uint32_t py,
                          uint32_t qx, uint32_t qy, double planeSigma, double normalPower);

} // namespace hush::passes_test::reference
