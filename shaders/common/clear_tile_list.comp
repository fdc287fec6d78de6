#version 450
// Resets a tile list (common/tile_list.glsl) before its classifying pass: no tile
// listed, so the listed pass's dispatch is (0, 1, 1) workgroups until one is. A shader
// rather than a buffer fill, so that the graph sees one kind of access on it.
layout(local_size_x = 64) in;

layout(set = 0, binding = 0, std430) writeonly buffer TileListBlock { uint values[]; } tiles;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < uint(tiles.values.length())) {
        tiles.values[i] = i == 1u || i == 2u ? 1u : 0u;
    }
}
