#version 450
#extension GL_GOOGLE_include_directive : require
// Render graph history tests (r32ui):
//   seen = historyValid ? history : 0xFFFFFFFF     (what this frame read of last frame)
//   acc  = (historyValid ? history : 0) + input + add
// The history is not read at all when it is invalid (it holds nothing then).
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, r32ui) uniform readonly uimage2D history;
layout(set = 0, binding = 1, r32ui) uniform readonly uimage2D current;
layout(set = 0, binding = 2, r32ui) uniform writeonly uimage2D acc;
layout(set = 0, binding = 3, r32ui) uniform writeonly uimage2D seen;

layout(push_constant) uniform Params {
    uint historyValid;
    uint add;
} params;

void main() {
    ivec2 p = hushPixel();
    if (!hushInside(p, imageSize(acc))) {
        return;
    }
    uint h = 0u;
    uint s = 0xFFFFFFFFu;
    if (params.historyValid != 0u) {
        h = imageLoad(history, p).x;
        s = h;
    }
    imageStore(seen, p, uvec4(s));
    imageStore(acc, p, uvec4(h + imageLoad(current, p).x + params.add));
}
