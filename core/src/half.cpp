#include <hush/core/half.hpp>

#define IMATH_HALF_NO_LOOKUP_TABLE
#include <Imath/half.h>

namespace hush::core {

float halfToFloat(uint16_t bits) { return imath_half_to_float(bits); }
uint16_t floatToHalf(float value) { return imath_float_to_half(value); }

} // namespace hush::core
