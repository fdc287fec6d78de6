// SVGF temporal accumulation (Schied et al. 2017, Sec. 4.1; moments for Sec. 4.2):
// exponential moving average of illumination and of its luminance moments through
// the reprojection decision, a cumulative average while the history is short.
//
// Compiled as svgf/temporal_accumulation.comp (every pixel; with
// fallbackInListedTiles, 2x2 footprints only) and svgf/temporal_fallback.comp (the
// reprojection's listed tiles, every footprint): common/footprint_tiles.glsl.
#ifndef HUSH_SVGF_TEMPORAL_ACCUMULATION_GLSL
#define HUSH_SVGF_TEMPORAL_ACCUMULATION_GLSL

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D illumination;
layout(set = 0, binding = 1) uniform texture2D reprojection;
layout(set = 0, binding = 2) uniform texture2D color_history;
layout(set = 0, binding = 3) uniform texture2D moments_history;
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D color;
layout(set = 0, binding = 5, rgba32f) uniform writeonly image2D moments;
#ifdef HUSH_LISTED_TILES
#define HUSH_TILE_LIST_BINDING 6
#endif
#include "common/footprint_tiles.glsl"

layout(push_constant) uniform Params {
    float alpha;
    float momentsAlpha;
    float maxHistoryLength;
    uint historyValid;
} params;

// |luminance| beyond this would square past fp32's range in the second moment.
const float kMaxMomentLuminance = 1e18;

void main() {
    ivec2 p = footprintPixel(imageSize(color));
    if (!hushInside(p, imageSize(color))) {
        return;
    }
    vec3 c = texelFetch(illumination, p, 0).rgb;
    float l = clamp(dot(c, vec3(0.2126, 0.7152, 0.0722)), -kMaxMomentLuminance, kMaxMomentLuminance);
    vec2 mu = vec2(l, l * l);

    ReprojectionFootprint f;
    bool reprojected = params.historyValid != 0u && reprojectionFootprint(texelFetch(reprojection, p, 0), f);
    if (!reprojected) {
        // Disocclusion, first frame or reset: the history starts again at this sample.
        imageStore(color, p, vec4(c, 1.0));
        imageStore(moments, p, vec4(mu, 1.0, 0.0));
        return;
    }
    if (footprintDeferred(f)) {
        return;
    }
    vec3 prevColor = fetchHistory(color_history, f).rgb;
    vec4 prevMoments = fetchHistory(moments_history, f);
    float n = min(max(prevMoments.z, 0.0) + 1.0, max(params.maxHistoryLength, 1.0));
    float a = max(params.alpha, 1.0 / n);            // n >= 1
    float am = max(params.momentsAlpha, 1.0 / n);
    imageStore(color, p, vec4(a * c + (1.0 - a) * prevColor, 1.0));
    imageStore(moments, p, vec4(am * mu + (1.0 - am) * prevMoments.xy, n, 0.0));
}

#endif
