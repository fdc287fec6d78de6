#pragma once
// Texel data for the format tests, in each format's memory layout (tightly packed,
// little-endian channels), and a comparison that names the first texel that differs.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <hush/rhi/format.hpp>

namespace hush::test {

// `texels` texels of `format`: the channel type's edge values first, then pseudo-random
// bit patterns (any bits, NaNs included). Unorm8 data holds every value 0..255 when
// there are at least 256 channels.
//   fp16 edges: +-0, 1, +-65504 (max), 2^-14 (min normal), 2^-24 and 2^-15 (subnormals),
//               0x03FF (max subnormal), +-Inf, quiet and signalling NaNs
//   fp32 edges: +-0, 1, +-FLT_MAX, FLT_MIN, +-denorm_min, +-Inf, NaNs with payloads, 65504
//   uint32 edges: 0, 1, 0x7FFFFFFF, 0x80000000, 0xFFFFFFFF (max)
std::vector<std::byte> edgeTexels(rhi::Format format, uint32_t texels, uint32_t seed);

// Like edgeTexels, but only values a shader's imageLoad/imageStore must reproduce:
// finite floats (NaN and Inf excluded), subnormals kept (compare with allowFlush).
std::vector<std::byte> finiteTexels(rhi::Format format, uint32_t texels, uint32_t seed);

// "" when equal; else where and how the first difference shows. With allowFlush, a
// float subnormal in `expected` also matches a zero of the same sign in `got` (Vulkan
// lets shaders and format conversions flush denormals).
std::string firstDifference(rhi::Format format, const std::vector<std::byte>& expected,
                            const std::vector<std::byte>& got, uint32_t width, bool allowFlush = false);

// The bytes of the rectangle [x, x + w) x [y, y + h) of a tightly packed image.
std::vector<std::byte> crop(const std::vector<std::byte>& image, uint32_t imageWidth, uint32_t bytesPerTexel,
                            uint32_t x, uint32_t y, uint32_t w, uint32_t h);
// Copies a tightly packed w x h rectangle into an image at (x, y).
void paste(std::vector<std::byte>& image, uint32_t imageWidth, uint32_t bytesPerTexel,
           const std::vector<std::byte>& rect, uint32_t x, uint32_t y, uint32_t w, uint32_t h);

} // namespace hush::test
