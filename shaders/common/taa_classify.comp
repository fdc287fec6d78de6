#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// TAA over every pixel whose reprojection keeps a whole 2x2 footprint or none; the
// tiles with a partial footprint are listed for common/taa_partial.comp (common/taa.glsl).
#define HUSH_TAA_CLASSIFY
#include "common/taa.glsl"
