#pragma once
// Image: a CPU image of float channels, row-major from the top-left pixel
// (DESIGN.md: pixel (0,0) is top-left, centres at +0.5).
#include <cstdint>
#include <vector>

namespace hush::tracer {

struct Image {
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t channels = 0;
    std::vector<float> pixels;   // width * height * channels

    Image() = default;
    Image(uint32_t w, uint32_t h, uint32_t c, float fill = 0.0f)
        : width(w), height(h), channels(c), pixels(size_t(w) * h * c, fill) {}

    float* at(uint32_t x, uint32_t y) { return pixels.data() + (size_t(y) * width + x) * channels; }
    const float* at(uint32_t x, uint32_t y) const { return pixels.data() + (size_t(y) * width + x) * channels; }
    bool empty() const { return pixels.empty(); }
};

} // namespace hush::tracer
