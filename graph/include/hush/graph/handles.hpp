#pragma once
// Typed, versioned handles (Filament's FrameGraph idea): a handle names one version
// of one resource. Writing a resource returns the next version; declaring a use of
// a version after a newer one exists is a "stale handle" error at compile time.
#include <cstdint>

namespace hush::graph {

inline constexpr uint32_t kNone = ~0u;

template <class Tag>
struct ResourceHandle {
    uint32_t index = kNone;
    uint32_t version = 0;
    bool valid() const { return index != kNone; }
    explicit operator bool() const { return valid(); }
    friend bool operator==(const ResourceHandle&, const ResourceHandle&) = default;
};

struct TextureTag {};
struct BufferTag {};
using TextureHandle = ResourceHandle<TextureTag>;
using BufferHandle = ResourceHandle<BufferTag>;

// A bind group declared by a pass at setup, made for each physical resource set at
// compile time, and fetched by the execute step.
struct BindGroupHandle {
    uint32_t pass = kNone;
    uint32_t index = kNone;
    bool valid() const { return index != kNone; }
};

} // namespace hush::graph
