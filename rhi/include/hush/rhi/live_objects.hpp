#pragma once
// How many RHI objects are alive right now, process-wide, by kind: what a leak
// check reads (the soak benchmark and test, docs/reliability.md). An object counts
// from its creation (or import) to the release of its last handle and of the last
// submission that kept it; the count costs two atomic additions per object.
#include <array>
#include <cstddef>
#include <cstdint>

namespace hush::rhi {

enum class ObjectKind : uint8_t {
    Instance, Device, Buffer, MemoryBlock, Texture, TextureView, Sampler, ShaderModule,
    BindGroupLayout, BindGroup, ComputePipeline, QuerySet, CommandBuffer, CommandEncoder,
};
inline constexpr std::size_t kObjectKindCount = std::size_t(ObjectKind::CommandEncoder) + 1;

const char* toString(ObjectKind kind);   // "texture"

struct LiveObjects {
    std::array<int64_t, kObjectKindCount> count{};
    int64_t operator[](ObjectKind kind) const { return count[std::size_t(kind)]; }
    int64_t total() const;
};

LiveObjects liveObjects();

} // namespace hush::rhi
