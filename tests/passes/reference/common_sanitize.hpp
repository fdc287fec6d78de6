#pragma once
// CPU reference of passes/common/sanitize, written from the node header,
// independently of the shader.
#include <cstddef>

#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

// Non-finite -> replacement, then clamp; returns the pixels with any non-finite component.
FloatImage sanitize(const FloatImage& in, float lo, float hi, float replacement, size_t& replacedPixels);

} // namespace hush::passes_test::reference
