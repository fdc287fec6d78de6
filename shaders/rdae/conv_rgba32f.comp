#version 450
#extension GL_GOOGLE_include_directive : require
// RDAE 3x3 convolution, rgba32f tensors (RdaeSettings::halfPrecision off; rdae/conv.glsl).
#define HUSH_TENSOR_FORMAT rgba32f
#include "rdae/conv.glsl"
