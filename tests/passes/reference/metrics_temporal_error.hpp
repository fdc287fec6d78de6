#pragma once
// CPU reference of passes/metrics/temporal_error (SVGF's temporal error, Sec. 5.4),
// in double precision, written from the definition (docs/passes/metrics.md)
// independently of the shaders.
#include <cstddef>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// Mean over pixels of the Rec. 709 luminance of |current - previous|. A pixel with a
// non-finite RGB component in either image is left out and counted.
struct TemporalErrorResult {
    double error = 0;
    size_t pixels = 0, nonFinitePixels = 0;
};
TemporalErrorResult temporalError(const FloatImage& current, const FloatImage& previous);

} // namespace hush::passes_test::reference
