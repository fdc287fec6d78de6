#pragma once
#include <cstdint>
#include <string>

#include <hush/rhi/format.hpp>
#include <hush/rhi/handle.hpp>

namespace hush::rhi {

class TextureView;

struct TextureDesc {
    std::string label;
    Extent2D size;
    Format format = Format::RGBA16Float;
    TextureUsage usage = TextureUsage::StorageBinding | TextureUsage::TextureBinding;
    uint32_t mipLevelCount = 1;
};

class Texture : public Handle<detail::TextureImpl> {
public:
    using Handle::Handle;

    const std::string& label() const;
    Extent2D size() const;
    uint32_t width() const { return size().width; }
    uint32_t height() const { return size().height; }
    Format format() const;
    TextureUsage usage() const;
    uint32_t mipLevelCount() const;
    uint64_t byteSize() const;   // tightly packed texels of mip 0

    // The view of all mips, made once with the texture.
    TextureView defaultView() const;
    TextureView createView(uint32_t baseMipLevel, uint32_t mipLevelCount = 1) const;
};

class TextureView : public Handle<detail::TextureViewImpl> {
public:
    using Handle::Handle;
    Texture texture() const;
    Format format() const;
    uint32_t baseMipLevel() const;
    uint32_t mipLevelCount() const;
};

enum class FilterMode : uint8_t { Nearest, Linear };
enum class AddressMode : uint8_t { ClampToEdge, Repeat, MirrorRepeat };

struct SamplerDesc {
    std::string label;
    FilterMode magFilter = FilterMode::Linear;
    FilterMode minFilter = FilterMode::Linear;
    AddressMode addressModeU = AddressMode::ClampToEdge;
    AddressMode addressModeV = AddressMode::ClampToEdge;
};

class Sampler : public Handle<detail::SamplerImpl> {
public:
    using Handle::Handle;
    const std::string& label() const;
};

} // namespace hush::rhi
