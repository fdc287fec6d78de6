#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
// SVGF variance estimation, 7x7 spatial estimate included, over the tiles that
// svgf/variance_estimate.comp listed (svgf/variance_estimate.glsl).
#define HUSH_LISTED_TILES
#include "svgf/variance_estimate.glsl"
