#pragma once
// Bind group layouts (reflected from SPIR-V, or written by hand) and bind groups.
// Creating a bind group checks it against its layout, entry by entry, and names the
// pipeline, set, binding and both kinds when something does not fit.
#include <cstdint>
#include <string>
#include <vector>

#include <hush/rhi/buffer.hpp>
#include <hush/rhi/texture.hpp>

namespace hush::rhi {

enum class BindingKind : uint8_t {
    UniformBuffer,
    StorageBuffer,            // read-write
    ReadOnlyStorageBuffer,
    SampledTexture,           // texture2D, paired with a separate sampler
    CombinedTextureSampler,   // sampler2D
    StorageTexture,           // image2D with a format qualifier
    Sampler,
};
std::string_view toString(BindingKind kind);

enum class StorageAccess : uint8_t { ReadWrite, ReadOnly, WriteOnly };
std::string_view toString(StorageAccess access);

struct BindGroupLayoutEntry {
    uint32_t binding = 0;
    BindingKind kind = BindingKind::StorageBuffer;
    std::string name;                          // the shader's variable name, if known
    Format storageFormat = Format::Undefined;  // StorageTexture only
    StorageAccess access = StorageAccess::ReadWrite;  // StorageTexture only
    uint32_t count = 1;                        // array size
    friend bool operator==(const BindGroupLayoutEntry&, const BindGroupLayoutEntry&) = default;
};

// What a kind and format look like in messages: "storage texture rgba16float (write-only)".
std::string describe(const BindGroupLayoutEntry& entry);

struct BindGroupLayoutDesc {
    std::string label;
    std::vector<BindGroupLayoutEntry> entries;
};

class BindGroupLayout : public Handle<detail::BindGroupLayoutImpl> {
public:
    using Handle::Handle;
    const std::string& label() const;
    const std::vector<BindGroupLayoutEntry>& entries() const;
    const BindGroupLayoutEntry* findBinding(uint32_t binding) const;
    const BindGroupLayoutEntry* findName(std::string_view name) const;
};

inline constexpr uint32_t kBindingByName = ~0u;

// One resource for one binding. Give `binding`, or leave it and give `name` (the
// shader's variable name, from reflection). Set exactly one of buffer,
// texture/textureView, sampler, or textureView and sampler for a combined binding.
struct BindGroupEntry {
    uint32_t binding = kBindingByName;
    std::string name;
    Buffer buffer;
    uint64_t offset = 0;
    uint64_t size = kWholeSize;
    Texture texture;           // shorthand for texture.defaultView()
    TextureView textureView;
    Sampler sampler;
};

struct BindGroupDesc {
    std::string label;
    BindGroupLayout layout;
    std::vector<BindGroupEntry> entries;
};

class BindGroup : public Handle<detail::BindGroupImpl> {
public:
    using Handle::Handle;
    const std::string& label() const;
    BindGroupLayout layout() const;
};

} // namespace hush::rhi
