// Body of shaders/bmfr/accumulate*.comp. The including .comp declares the output
// image `accumulated` (binding 3) with its literal format qualifier and
// vec4 bmfrStorable(vec4) (identity for rgba32f, clamp to +-65504 for rgba16f).
// BMFR temporal accumulation (Koskela et al. 2019, Sec. 3.1 and 3.3): cumulative
// moving average of the reprojected history and the new sample until the new
// sample's weight would fall below minWeight, then exponential with minWeight.
// The history's colour and sample count are read through the same renormalised
// footprint (Sec. 3.1: "Also the sample count data is sampled using the same custom
// bilinear sampling and the result is rounded to the closest integer value").
//
// Every pixel from bmfr/accumulate*.comp (with fallbackInListedTiles, 2x2 footprints
// only); the reprojection's listed tiles, every footprint, from
// bmfr/accumulate_fallback*.comp: common/footprint_tiles.glsl.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D current;   // this frame's sample, rgb
layout(set = 0, binding = 1) uniform texture2D reprojection;
layout(set = 0, binding = 2) uniform texture2D history;   // rgb colour, a sample count
#ifdef HUSH_LISTED_TILES
#define HUSH_TILE_LIST_BINDING 4
#endif
#include "common/footprint_tiles.glsl"

layout(push_constant) uniform Params {
    float minWeight;     // in (0, 1], checked on the CPU
    float countCap;      // ceil(1 / minWeight) >= 1
    uint historyValid;
} params;

void main() {
    ivec2 p = footprintPixel(imageSize(accumulated));
    if (!hushInside(p, imageSize(accumulated))) {
        return;
    }
    vec3 x = texelFetch(current, p, 0).rgb;
    ReprojectionFootprint f;
    bool reprojected = params.historyValid != 0u && reprojectionFootprint(texelFetch(reprojection, p, 0), f);
    if (!reprojected) {
        // Disocclusion, first frame or reset: the count restarts at this sample.
        imageStore(accumulated, p, bmfrStorable(vec4(x, 1.0)));
        return;
    }
    if (footprintDeferred(f)) {
        return;
    }
    vec4 prev = fetchHistory(history, f);
    // The count is an integer in [1, cap] per tap; its weighted mean is rounded.
    float n = min(floor(clamp(prev.a, 0.0, params.countCap) + 0.5) + 1.0, params.countCap);
    float a = max(params.minWeight, 1.0 / n);   // n >= 1
    imageStore(accumulated, p, bmfrStorable(vec4(a * x + (1.0 - a) * prev.rgb, n)));
}
