#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// SVGF temporal accumulation over the tiles where the reprojection ran its 3x3
// fallback, every footprint (svgf/temporal_accumulation.glsl).
#define HUSH_LISTED_TILES
#include "svgf/temporal_accumulation.glsl"
