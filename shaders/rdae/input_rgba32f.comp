#version 450
#extension GL_GOOGLE_include_directive : require
// RDAE input tensor, rgba32f (rdae/input.glsl).
#define HUSH_TENSOR_FORMAT rgba32f
#include "rdae/input.glsl"
