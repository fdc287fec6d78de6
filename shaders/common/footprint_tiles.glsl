// A pass that reads a history through the reprojection decision, split by the
// reprojection's tile list (passes/common/reproject.hpp, reprojectionFallbackTiles).
// Mode-2 pixels (3x3 footprints) exist only in the tiles where the reprojection
// tried its fallback, which it listed; everywhere else a footprint has at most the
// 2x2 taps. So the pass runs in one of three variants:
//   fallbackInListedTiles = 0   every pixel, every footprint (one dispatch);
//   fallbackInListedTiles = 1   every pixel, 2x2 taps only; a mode-2 pixel is left
//                               to the listed variant (4 history fetches, not 9);
//   HUSH_LISTED_TILES defined   every pixel of the listed tiles, every footprint,
//                               dispatched indirectly over the reprojection's list.
// Lavapipe runs the nine taps of fetchFootprint for every pixel whatever its mode
// (docs/passes/common.md, "Tile lists"). The including shader defines
// HUSH_TILE_LIST_BINDING when HUSH_LISTED_TILES is (and only then: no other variant
// binds the list), and uses 8x8 workgroups.
// Needs GL_EXT_samplerless_texture_functions.
#ifndef HUSH_COMMON_FOOTPRINT_TILES_GLSL
#define HUSH_COMMON_FOOTPRINT_TILES_GLSL
#include "common/grid.glsl"
#include "common/reprojection.glsl"

#include "common/tile_list.glsl"
#ifndef HUSH_LISTED_TILES
layout(constant_id = 0) const uint fallbackInListedTiles = 0u;
#endif

// The reprojection's tile (common/reproject.glsl's kTile): one 8x8 workgroup.
const uvec2 kFootprintTile = uvec2(8, 8);

// This invocation's pixel.
ivec2 footprintPixel(ivec2 size) {
    return hushTilePixel(size, kFootprintTile);
}

// True where the listed variant does this pixel instead (a 3x3 footprint).
bool footprintDeferred(ReprojectionFootprint f) {
#ifdef HUSH_LISTED_TILES
    return false;
#else
    return fallbackInListedTiles != 0u && f.width == 3;
#endif
}

// fetchFootprint, by the 2x2 taps alone where no 3x3 footprint reaches this variant.
vec4 fetchHistory(texture2D history, ReprojectionFootprint f) {
#ifndef HUSH_LISTED_TILES
    if (fallbackInListedTiles != 0u) {
        return fetchFootprint2x2(history, f);
    }
#endif
    return fetchFootprint(history, f);
}

#endif
