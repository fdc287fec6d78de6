#include "support/texel_data.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "support/gpu_context.hpp"
#include "support/half.hpp"

namespace hush::test {

namespace {

using rhi::ChannelType;

uint32_t channelBytes(ChannelType type) {
    switch (type) {
    case ChannelType::Unorm8: return 1;
    case ChannelType::Float16: return 2;
    case ChannelType::Float32:
    case ChannelType::Uint32: return 4;
    }
    return 4;
}

template <class T> std::vector<std::byte> toBytes(const std::vector<T>& values) {
    std::vector<std::byte> out(values.size() * sizeof(T));
    std::memcpy(out.data(), values.data(), out.size());
    return out;
}

std::vector<uint16_t> halfEdges() {
    return {0x0000, 0x8000, floatToHalf(1.0f), floatToHalf(65504.0f), floatToHalf(-65504.0f),
            floatToHalf(std::ldexp(1.0f, -14)), floatToHalf(std::ldexp(1.0f, -24)),
            floatToHalf(std::ldexp(1.0f, -15)), floatToHalf(std::ldexp(1023.0f, -24)),
            floatToHalf(-std::ldexp(1.0f, -24)), 0x7C00, 0xFC00, 0x7E00, 0x7C01, 0xFE3F};
}

std::vector<uint32_t> floatEdges() {
    auto bits = [](float f) { return std::bit_cast<uint32_t>(f); };
    using L = std::numeric_limits<float>;
    return {bits(0.0f),   0x80000000u,       bits(1.0f),          bits(L::max()),      bits(-L::max()),
            bits(L::min()), bits(L::denorm_min()), bits(-L::denorm_min()), bits(L::infinity()), bits(-L::infinity()),
            0x7FC00000u,  0x7FC12345u,       0xFFFFFFFFu,         0x7F800001u,         bits(65504.0f)};
}

bool isHalfSubnormal(uint16_t h) { return (h & 0x7C00) == 0 && (h & 0x3FF) != 0; }
bool isFloatSubnormal(uint32_t f) { return (f & 0x7F800000u) == 0 && (f & 0x7FFFFFu) != 0; }

} // namespace

std::vector<std::byte> edgeTexels(rhi::Format format, uint32_t texels, uint32_t seed) {
    const auto& info = rhi::formatInfo(format);
    const size_t count = size_t(texels) * info.channels;
    Lcg rng(seed);
    switch (info.channelType) {
    case ChannelType::Unorm8: {
        std::vector<uint8_t> v(count);
        for (size_t i = 0; i < count; ++i) v[i] = i < 256 ? uint8_t(255 - i) : uint8_t(rng.next());
        return toBytes(v);
    }
    case ChannelType::Float16: {
        std::vector<uint16_t> v = halfEdges();
        v.resize(std::min(v.size(), count));
        while (v.size() < count) v.push_back(uint16_t(rng.next()));
        return toBytes(v);
    }
    case ChannelType::Float32: {
        std::vector<uint32_t> v = floatEdges();
        v.resize(std::min(v.size(), count));
        while (v.size() < count) v.push_back(rng.next());
        return toBytes(v);
    }
    case ChannelType::Uint32: {
        std::vector<uint32_t> v = {0u, 1u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFFu};
        v.resize(std::min(v.size(), count));
        while (v.size() < count) v.push_back(rng.next());
        return toBytes(v);
    }
    }
    return {};
}

std::vector<std::byte> finiteTexels(rhi::Format format, uint32_t texels, uint32_t seed) {
    const auto& info = rhi::formatInfo(format);
    const size_t count = size_t(texels) * info.channels;
    Lcg rng(seed);
    switch (info.channelType) {
    case ChannelType::Float16: {
        std::vector<uint16_t> v;
        for (uint16_t h : halfEdges())
            if ((h & 0x7C00) != 0x7C00) v.push_back(h);
        v.resize(std::min(v.size(), count));
        while (v.size() < count) {
            const auto h = uint16_t(rng.next());
            if ((h & 0x7C00) != 0x7C00) v.push_back(h);
        }
        return toBytes(v);
    }
    case ChannelType::Float32: {
        std::vector<uint32_t> v;
        for (uint32_t f : floatEdges())
            if ((f & 0x7F800000u) != 0x7F800000u) v.push_back(f);
        v.resize(std::min(v.size(), count));
        while (v.size() < count) {
            const uint32_t f = rng.next();
            if ((f & 0x7F800000u) != 0x7F800000u) v.push_back(f);
        }
        return toBytes(v);
    }
    default: return edgeTexels(format, texels, seed);   // every unorm8 and uint32 value is representable
    }
}

std::string firstDifference(rhi::Format format, const std::vector<std::byte>& expected,
                            const std::vector<std::byte>& got, uint32_t width, bool allowFlush) {
    const auto& info = rhi::formatInfo(format);
    std::ostringstream out;
    if (expected.size() != got.size()) {
        out << "size differs: expected " << expected.size() << " bytes, got " << got.size();
        return out.str();
    }
    const uint32_t bytes = channelBytes(info.channelType);
    const size_t channels = expected.size() / bytes;
    for (size_t i = 0; i < channels; ++i) {
        uint32_t e = 0, g = 0;
        std::memcpy(&e, expected.data() + i * bytes, bytes);
        std::memcpy(&g, got.data() + i * bytes, bytes);
        if (e == g) continue;
        if (allowFlush && info.channelType == ChannelType::Float16 && isHalfSubnormal(uint16_t(e)) &&
            g == (e & 0x8000u))
            continue;
        if (allowFlush && info.channelType == ChannelType::Float32 && isFloatSubnormal(e) && g == (e & 0x80000000u))
            continue;
        const size_t texel = i / info.channels;
        out << toString(format) << " texel (" << texel % width << ", " << texel / width << ") channel "
            << i % info.channels << ": expected 0x" << std::hex << e << ", got 0x" << g << std::dec;
        if (info.channelType == ChannelType::Float16)
            out << " (" << halfToFloat(uint16_t(e)) << " vs " << halfToFloat(uint16_t(g)) << ")";
        if (info.channelType == ChannelType::Float32)
            out << " (" << std::bit_cast<float>(e) << " vs " << std::bit_cast<float>(g) << ")";
        return out.str();
    }
    return "";
}

std::vector<std::byte> crop(const std::vector<std::byte>& image, uint32_t imageWidth, uint32_t bytesPerTexel,
                            uint32_t x, uint32_t y, uint32_t w, uint32_t h) {
    std::vector<std::byte> out(size_t(w) * h * bytesPerTexel);
    for (uint32_t row = 0; row < h; ++row)
        std::memcpy(out.data() + size_t(row) * w * bytesPerTexel,
                    image.data() + (size_t(y + row) * imageWidth + x) * bytesPerTexel, size_t(w) * bytesPerTexel);
    return out;
}

void paste(std::vector<std::byte>& image, uint32_t imageWidth, uint32_t bytesPerTexel,
           const std::vector<std::byte>& rect, uint32_t x, uint32_t y, uint32_t w, uint32_t h) {
    for (uint32_t row = 0; row < h; ++row)
        std::memcpy(image.data() + (size_t(y + row) * imageWidth + x) * bytesPerTexel,
                    rect.data() + size_t(row) * w * bytesPerTexel, size_t(w) * bytesPerTexel);
}

} // namespace hush::test
