#pragma once
// CPU reference of Mara et al. 2017's temporal stages (seed 000 Sec. 3.4, Eq. 11), in
// double precision, written from the formulas of passes/include/hush/passes/mara/
// temporal.hpp and docs/passes/mara.md, independently of the shaders.
#include <array>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

struct MaraTemporalParams {
    double hysteresis = 0.98, d0 = 0.05, d1 = 0.07, metresPerUnit = 1.0;
    bool historyValid = true;
};

// Stage 3: rgba (rgb the blend, a the confidence c); last frame's sample at
// p + 0.5 + motion. All images rgb(a) at one size; motion rg.
FloatImage maraMatteTemporal(const FloatImage& current, const FloatImage& motion, const FloatImage& position,
                             const FloatImage& history, const FloatImage& positionHistory,
                             const MaraTemporalParams& params);

// Stage 8: last frame's sample where `previousViewProjection` (column-major) projects
// the virtual position.
FloatImage maraGlossyTemporal(const FloatImage& current, const FloatImage& virtualpos, const FloatImage& history,
                              const FloatImage& virtualposHistory, const std::array<double, 16>& previousViewProjection,
                              const MaraTemporalParams& params);

} // namespace hush::passes_test::reference
