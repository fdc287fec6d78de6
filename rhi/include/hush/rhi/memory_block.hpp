#pragma once
// MemoryBlock: one device-memory allocation that several textures can be placed in,
// so that transient textures whose lifetimes do not overlap share bytes.
#include <cstdint>
#include <string>

#include <hush/rhi/handle.hpp>

namespace hush::rhi {

struct MemoryRequirements {
    uint64_t size = 0;
    uint64_t alignment = 1;
    uint32_t memoryTypeBits = 0;
};

struct MemoryBlockDesc {
    std::string label;
    uint64_t size = 0;
    uint32_t memoryTypeBits = ~0u;   // intersection of the placed textures' requirements
};

namespace detail { struct MemoryBlockImpl; }

class MemoryBlock : public Handle<detail::MemoryBlockImpl> {
public:
    using Handle::Handle;
    const std::string& label() const;
    uint64_t size() const;
};

} // namespace hush::rhi
