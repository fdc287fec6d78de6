#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
// SVGF variance estimation over every tile: the temporal variance where the history
// is long; the tiles where it is short are listed for svgf/variance_spatial.comp
// (svgf/variance_estimate.glsl).
#include "svgf/variance_estimate.glsl"
