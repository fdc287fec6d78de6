#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// SVGF temporal accumulation over every pixel (svgf/temporal_accumulation.glsl).
#include "svgf/temporal_accumulation.glsl"
