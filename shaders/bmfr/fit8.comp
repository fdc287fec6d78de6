#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// BMFR fit of 8x8 blocks, rgba32f output (the default; bmfr/fit.glsl).
#define HUSH_BMFR_FIT_BLOCK 8
layout(set = 0, binding = 6, rgba32f) uniform writeonly image2D fitted;
vec4 bmfrStorable(vec4 v) { return v; }
#include "bmfr/fit.glsl"
