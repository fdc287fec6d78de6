#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// The reprojection decision over every tile; the tiles where a pixel needs the 3x3
// fallback are listed for common/reproject_fallback.comp (common/reproject.glsl).
#include "common/reproject.glsl"
