#include <hush/passes/common/normal_power.hpp>

#include <cmath>
#include <utility>

namespace hush::passes {

uint32_t wholeExponent(float exponent) {
    // Up to 16 squarings; past that pow() is as fast and the weight is 0 anyway
    // for any cosine a unit normal pair can give but 1.
    constexpr float kMaxWhole = 65535.0f;
    if (!(exponent >= 1.0f && exponent <= kMaxWhole) || std::floor(exponent) != exponent) return 0;
    return uint32_t(exponent);
}

rhi::ConstantEntry normalPowerConstant(std::string name, float exponent) {
    return {std::move(name), double(wholeExponent(exponent))};
}

} // namespace hush::passes
