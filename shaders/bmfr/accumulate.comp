#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// BMFR temporal accumulation, rgba32f output (the default; bmfr/accumulate.glsl).
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D accumulated;
vec4 bmfrStorable(vec4 v) { return v; }
#include "bmfr/accumulate.glsl"
