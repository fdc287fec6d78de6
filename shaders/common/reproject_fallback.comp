#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// The reprojection decision, 3x3 fallback included, over the tiles that
// common/reproject.comp listed (common/reproject.glsl).
#define HUSH_LISTED_TILES
#include "common/reproject.glsl"
