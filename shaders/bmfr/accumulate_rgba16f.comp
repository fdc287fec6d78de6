#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// BMFR temporal accumulation, rgba16f output (BmfrSettings::halfPrecision;
// bmfr/accumulate.glsl). Clamped to the largest finite half, 65504, so that bright
// demodulated illumination saturates instead of becoming Inf in the output and its
// history (numerical contract). The count in alpha is <= ceil(1 / minWeight), exact.
layout(set = 0, binding = 3, rgba16f) uniform writeonly image2D accumulated;
vec4 bmfrStorable(vec4 v) { return clamp(v, vec4(-65504.0), vec4(65504.0)); }
#include "bmfr/accumulate.glsl"
