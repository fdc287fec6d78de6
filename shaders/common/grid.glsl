// One invocation per pixel: how a hush kernel finds its pixel, and skips the
// invocations that a dispatch rounds up past the image edge (dispatches cover
// whole workgroups, so odd sizes always leave some).
#ifndef HUSH_COMMON_GRID_GLSL
#define HUSH_COMMON_GRID_GLSL

ivec2 hushPixel() {
    return ivec2(gl_GlobalInvocationID.xy);
}

bool hushInside(ivec2 pixel, ivec2 size) {
    return all(greaterThanEqual(pixel, ivec2(0))) && all(lessThan(pixel, size));
}

#endif
