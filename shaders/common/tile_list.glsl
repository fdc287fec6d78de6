// Tiles that need a kernel's rare, costly case (passes/include/hush/passes/common/
// tile_list.hpp). A branch a vector of pixels does not take still costs on lavapipe,
// which runs every branch under a lane mask, and on a GPU whenever one lane of a warp
// takes it. So a kernel with such a case is dispatched twice: its classifying variant
// over every tile, which does the common case and lists each tile where a pixel needs
// the rare one; then its listed variant (HUSH_LISTED_TILES defined) by an indirect
// dispatch of one workgroup per listed tile, doing the whole kernel there.
//
// Buffer `tiles`, uint32: [0 .. 2] the listed pass's workgroup counts (x = tiles listed,
// then 1, 1); [3] unused; [4 .. 4 + n) one flag per tile, 1 once listed; [4 + n ..
// 4 + 2n) the listed tiles' indices (row-major), n = the image's tile count.
// common/clear_tile_list.comp resets it every frame. The including shader defines
// HUSH_TILE_LIST_BINDING in its classifying and listed variants; a variant without
// it (a pass that neither lists nor reads the list) declares no buffer and works on
// its own tile. Needs a tile to be exactly one workgroup.
#ifndef HUSH_COMMON_TILE_LIST_GLSL
#define HUSH_COMMON_TILE_LIST_GLSL

#if defined(HUSH_LISTED_TILES) && !defined(HUSH_TILE_LIST_BINDING)
#error "a listed variant (HUSH_LISTED_TILES) reads the tile list: define HUSH_TILE_LIST_BINDING"
#elif defined(HUSH_LISTED_TILES)
layout(set = 0, binding = HUSH_TILE_LIST_BINDING, std430) readonly buffer TileListBlock {
    uint header[4];
    uint entries[];
} tiles;
#elif defined(HUSH_TILE_LIST_BINDING)
layout(set = 0, binding = HUSH_TILE_LIST_BINDING, std430) buffer TileListBlock {
    uint header[4];
    uint entries[];
} tiles;
#endif

// Tiles across and down an image of `size` pixels, `tile` pixels each.
uvec2 hushTileGrid(ivec2 size, uvec2 tile) {
    return (uvec2(max(size, ivec2(0))) + tile - 1u) / tile;
}

// The tile this workgroup covers, in tiles: its own in the classifying pass, the
// listed one in the listed pass.
uvec2 hushTile(ivec2 size, uvec2 tile) {
#ifdef HUSH_LISTED_TILES
    uvec2 grid = hushTileGrid(size, tile);
    uint index = tiles.entries[grid.x * grid.y + gl_WorkGroupID.x];
    return uvec2(index % grid.x, index / grid.x);
#else
    return gl_WorkGroupID.xy;
#endif
}

// This invocation's first pixel in that tile, `stride` pixels apart along each axis
// (1, 1: one pixel per invocation; kRow, 1: a row of kRow pixels each).
ivec2 hushTilePixel(ivec2 size, uvec2 tile, uvec2 stride) {
    return ivec2(hushTile(size, tile) * tile + gl_LocalInvocationID.xy * stride);
}

ivec2 hushTilePixel(ivec2 size, uvec2 tile) {
    return hushTilePixel(size, tile, uvec2(1u));
}

#if !defined(HUSH_LISTED_TILES) && defined(HUSH_TILE_LIST_BINDING)
// Lists this workgroup's tile for the listed pass, once however many of its
// invocations call it (the flag's exchange lets exactly one through).
void hushListTile(ivec2 size, uvec2 tile) {
    uvec2 grid = hushTileGrid(size, tile);
    uint index = gl_WorkGroupID.y * grid.x + gl_WorkGroupID.x;
    if (atomicExchange(tiles.entries[index], 1u) == 0u) {
        uint slot = atomicAdd(tiles.header[0], 1u);
        tiles.entries[grid.x * grid.y + slot] = index;
    }
}
#endif

#endif
