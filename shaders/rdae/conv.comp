#version 450
#extension GL_GOOGLE_include_directive : require
// RDAE 3x3 convolution, rgba16f tensors (the default; rdae/conv.glsl).
#define HUSH_TENSOR_FORMAT rgba16f
#include "rdae/conv.glsl"
