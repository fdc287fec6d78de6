#include "display_image.hpp"

#include <algorithm>
#include <cmath>

#include <hush/core/error.hpp>

namespace hush::cli {

namespace {
uint8_t srgbByte(float linear) {
    if (!(linear > 0.0f)) return 0;   // also NaN
    if (linear >= 1.0f) return 255;
    const float encoded = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    return uint8_t(std::lround(encoded * 255.0f));
}
} // namespace

std::vector<uint8_t> encodeSrgb8(const RgbaImage& image) {
    std::vector<uint8_t> bytes(size_t(image.width) * image.height * 3);
    for (size_t i = 0; i < size_t(image.width) * image.height; ++i)
        for (size_t c = 0; c < 3; ++c) bytes[i * 3 + c] = srgbByte(image.rgba[i * 4 + c]);
    return bytes;
}

RgbaImage toRgba(const tracer::Image& image) {
    RgbaImage out(image.width, image.height);
    for (size_t i = 0; i < size_t(image.width) * image.height; ++i) {
        for (uint32_t c = 0; c < 3; ++c)
            out.rgba[i * 4 + c] = image.pixels[i * image.channels + std::min(c, image.channels - 1)];
        out.rgba[i * 4 + 3] = 1.0f;
    }
    return out;
}

RgbaImage sideBySide(std::span<const RgbaImage* const> panels, uint32_t gap) {
    if (panels.empty()) return {};
    const uint32_t height = panels[0]->height;
    uint32_t width = 0;
    for (const auto* p : panels) {
        if (p->height != height) throw Error(ErrorKind::InvalidArgument, "side-by-side panels differ in height");
        width += p->width;
    }
    width += gap * uint32_t(panels.size() - 1);
    RgbaImage out(width, height);
    std::fill(out.rgba.begin(), out.rgba.end(), 1.0f);
    uint32_t x0 = 0;
    for (const auto* p : panels) {
        for (uint32_t y = 0; y < height; ++y)
            std::copy_n(p->rgba.begin() + ptrdiff_t(size_t(y) * p->width * 4), size_t(p->width) * 4,
                        out.rgba.begin() + ptrdiff_t((size_t(y) * width + x0) * 4));
        x0 += p->width + gap;
    }
    return out;
}

} // namespace hush::cli
