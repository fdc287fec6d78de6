#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// BMFR temporal accumulation, rgba32f output, over the tiles where the reprojection
// ran its 3x3 fallback (bmfr/accumulate.glsl).
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D accumulated;
vec4 bmfrStorable(vec4 v) { return v; }
#define HUSH_LISTED_TILES
#include "bmfr/accumulate.glsl"
