#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Sanitise one rg32f input (common/sanitize.glsl).
layout(set = 0, binding = 1, rg32f) uniform writeonly image2D dst;
#include "common/sanitize.glsl"
