#version 450
#extension GL_GOOGLE_include_directive : require
// RDAE 2x2 max pooling, rgba16f tensors (the default; rdae/pool.glsl).
#define HUSH_TENSOR_FORMAT rgba16f
#include "rdae/pool.glsl"
