#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// BMFR fit of 8x8 blocks, rgba16f output (BmfrSettings::halfPrecision;
// bmfr/fit.glsl). Only the stored result is half: the fit itself runs in fp32. Clamped
// to +-65504 (the largest finite half) so that no Inf reaches the post-accumulation.
#define HUSH_BMFR_FIT_BLOCK 8
layout(set = 0, binding = 6, rgba16f) uniform writeonly image2D fitted;
vec4 bmfrStorable(vec4 v) { return clamp(v, vec4(-65504.0), vec4(65504.0)); }
#include "bmfr/fit.glsl"
