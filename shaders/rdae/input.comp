#version 450
#extension GL_GOOGLE_include_directive : require
// RDAE input tensor, rgba16f (the default; rdae/input.glsl).
#define HUSH_TENSOR_FORMAT rgba16f
#include "rdae/input.glsl"
