#pragma once
// CPU images for what the CLI writes: RGBA float images, sRGB 8-bit encoding, and
// the side-by-side strip of the main job (panels left to right, 4-pixel gaps).
#include <cstdint>
#include <span>
#include <vector>

#include <hush/tracer/image.hpp>

namespace hush::cli {

struct RgbaImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;   // width * height * 4
    RgbaImage() = default;
    RgbaImage(uint32_t w, uint32_t h) : width(w), height(h), rgba(size_t(w) * h * 4, 0.0f) {}
};

// Linear [0, 1] -> sRGB-encoded bytes (IEC 61966-2-1 transfer function), RGB.
std::vector<uint8_t> encodeSrgb8(const RgbaImage& image);
// A 1-, 3- or 4-component tracer image as RGBA (alpha 1).
RgbaImage toRgba(const tracer::Image& image);
// Panels of equal height, left to right, separated by `gap` white columns.
RgbaImage sideBySide(std::span<const RgbaImage* const> panels, uint32_t gap = 4);

} // namespace hush::cli
