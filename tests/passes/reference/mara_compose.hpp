#pragma once
// CPU reference of Mara et al. 2017's composite (seed 000 Eq. 9, 10): direct +
// (1 - F)^2 albedo matte + F glossy, Schlick's F at the mirror direction.
#include <array>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// `glossy` may be nullptr (no glossy term).
FloatImage maraCompose(const FloatImage& direct, const FloatImage& matte, const FloatImage* glossy,
                       const FloatImage& albedo, const FloatImage& specular, const FloatImage& normalDepth,
                       const FloatImage& position, const std::array<double, 3>& camera);

} // namespace hush::passes_test::reference
