#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// BMFR temporal accumulation, rgba16f output (see bmfr/accumulate_rgba16f.comp), over
// the tiles where the reprojection ran its 3x3 fallback (bmfr/accumulate.glsl).
layout(set = 0, binding = 3, rgba16f) uniform writeonly image2D accumulated;
vec4 bmfrStorable(vec4 v) { return clamp(v, vec4(-65504.0), vec4(65504.0)); }
#define HUSH_LISTED_TILES
#include "bmfr/accumulate.glsl"
