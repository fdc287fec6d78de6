#pragma once
// IEEE 754 binary16 <-> binary32, for files and read-backs that store fp16 (weights,
// rgba16f textures). Imath's conversion (Debian's libimath-dev, OpenEXR's half),
// without its lookup table, so nothing links against libImath.
#include <cstdint>

namespace hush::core {

float halfToFloat(uint16_t bits);     // exact: every half is a float
uint16_t floatToHalf(float value);    // round to nearest even; overflow to +-inf

} // namespace hush::core
