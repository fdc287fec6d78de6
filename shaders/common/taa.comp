#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// TAA over every pixel, without a tile list (common/taa.glsl).
#include "common/taa.glsl"
