#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// TAA over the tiles common/taa_classify.comp listed, every footprint (common/taa.glsl).
#define HUSH_LISTED_TILES
#include "common/taa.glsl"
