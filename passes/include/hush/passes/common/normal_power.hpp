#pragma once
// The specialization constant that lets a shader evaluate a normal weight's power by
// repeated squaring (shaders/common/normal_power.glsl).
#include <cstdint>
#include <string>

#include <hush/rhi/pipeline.hpp>

namespace hush::passes {

// `exponent` if it is a whole number in 1 .. 65535, else 0 (the shader then calls pow()).
uint32_t wholeExponent(float exponent);

// The constant `name` (the shader's spelling, e.g. "wholeSigmaN") for `exponent`.
rhi::ConstantEntry normalPowerConstant(std::string name, float exponent);

} // namespace hush::passes
