#version 450
#extension GL_GOOGLE_include_directive : require
// RDAE 2x2 max pooling, rgba32f tensors (rdae/pool.glsl).
#define HUSH_TENSOR_FORMAT rgba32f
#include "rdae/pool.glsl"
