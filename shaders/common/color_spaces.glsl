// Colour-space helpers of the display nodes (tonemap, TAA).
#ifndef HUSH_COMMON_COLOR_SPACES_GLSL
#define HUSH_COMMON_COLOR_SPACES_GLSL

// Rec. 709 / sRGB primaries, linear values (ITU-R BT.709 luma coefficients).
float rec709Luminance(vec3 rgb) {
    return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
}

// YCoCg (Malvar & Sullivan 2003): the space Karis 2014 clamps TAA history in,
// because luma and chroma are decorrelated there and the box is tighter. The
// factors are powers of two, so both directions are exact up to the adds.
vec3 rgbToYCoCg(vec3 c) {
    return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b,
                0.5 * c.r - 0.5 * c.b,
                -0.25 * c.r + 0.5 * c.g - 0.25 * c.b);
}

vec3 yCoCgToRgb(vec3 c) {
    return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z);
}

#endif
