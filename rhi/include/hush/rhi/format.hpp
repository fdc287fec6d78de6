#pragma once
// Texture formats and usage flags, named after WebGPU's.
#include <cstdint>
#include <string>
#include <string_view>

namespace hush::rhi {

enum class Format : uint8_t {
    Undefined,
    R8Unorm,
    R16Float,
    R32Float,
    RG16Float,
    RG32Float,
    RGBA8Unorm,
    RGBA16Float,
    RGBA32Float,
    R32Uint,
};

inline constexpr Format kAllFormats[] = {
    Format::R8Unorm,   Format::R16Float,   Format::R32Float,    Format::RG16Float, Format::RG32Float,
    Format::RGBA8Unorm, Format::RGBA16Float, Format::RGBA32Float, Format::R32Uint,
};

enum class ChannelType : uint8_t { Unorm8, Float16, Float32, Uint32 };

struct FormatInfo {
    std::string_view name;       // WebGPU spelling: "rgba16float"
    std::string_view glslName;   // GLSL image format qualifier: "rgba16f"
    uint32_t channels = 0;
    uint32_t bytesPerPixel = 0;
    ChannelType channelType = ChannelType::Float32;
};

const FormatInfo& formatInfo(Format format);
inline std::string_view toString(Format format) { return formatInfo(format).name; }
// Parses either spelling ("rgba16float" or "rgba16f"); Format::Undefined if unknown.
Format parseFormat(std::string_view name);

template <class E>
struct FlagOps {
    static constexpr bool enabled = false;
};

enum class TextureUsage : uint32_t {
    None = 0,
    CopySrc = 1u << 0,
    CopyDst = 1u << 1,
    TextureBinding = 1u << 2,   // sampled in a shader
    StorageBinding = 1u << 3,   // imageLoad / imageStore
};

enum class BufferUsage : uint32_t {
    None = 0,
    MapRead = 1u << 0,    // host-visible, cached: read back results
    MapWrite = 1u << 1,   // host-visible: upload
    CopySrc = 1u << 2,
    CopyDst = 1u << 3,
    Uniform = 1u << 4,
    Storage = 1u << 5,
    Indirect = 1u << 6,
};

template <> struct FlagOps<TextureUsage> { static constexpr bool enabled = true; };
template <> struct FlagOps<BufferUsage> { static constexpr bool enabled = true; };

template <class E> requires FlagOps<E>::enabled
constexpr E operator|(E a, E b) { return E(uint32_t(a) | uint32_t(b)); }
template <class E> requires FlagOps<E>::enabled
constexpr E operator&(E a, E b) { return E(uint32_t(a) & uint32_t(b)); }
template <class E> requires FlagOps<E>::enabled
constexpr E& operator|=(E& a, E b) { return a = a | b; }
template <class E> requires FlagOps<E>::enabled
constexpr bool hasAny(E set, E bits) { return (uint32_t(set) & uint32_t(bits)) != 0; }
template <class E> requires FlagOps<E>::enabled
constexpr bool hasAll(E set, E bits) { return (uint32_t(set) & uint32_t(bits)) == uint32_t(bits); }

std::string toString(TextureUsage usage);  // "copy-src|storage"
std::string toString(BufferUsage usage);

struct Extent2D {
    uint32_t width = 0;
    uint32_t height = 0;
    friend bool operator==(const Extent2D&, const Extent2D&) = default;
};

} // namespace hush::rhi
