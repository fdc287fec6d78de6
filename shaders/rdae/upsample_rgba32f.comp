#version 450
#extension GL_GOOGLE_include_directive : require
// RDAE 2x2 nearest upsampling, rgba32f tensors (rdae/upsample.glsl).
#define HUSH_TENSOR_FORMAT rgba32f
#include "rdae/upsample.glsl"
