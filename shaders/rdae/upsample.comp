#version 450
#extension GL_GOOGLE_include_directive : require
// RDAE 2x2 nearest upsampling, rgba16f tensors (the default; rdae/upsample.glsl).
#define HUSH_TENSOR_FORMAT rgba16f
#include "rdae/upsample.glsl"
