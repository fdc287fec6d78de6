#include <hush/rhi/live_objects.hpp>

#include "objects.hpp"

namespace hush::rhi {

namespace detail {

std::atomic<int64_t>& liveCounter(ObjectKind kind) {
    static std::array<std::atomic<int64_t>, kObjectKindCount> counters{};
    return counters[std::size_t(kind)];
}

} // namespace detail

const char* toString(ObjectKind kind) {
    switch (kind) {
    case ObjectKind::Instance: return "instance";
    case ObjectKind::Device: return "device";
    case ObjectKind::Buffer: return "buffer";
    case ObjectKind::MemoryBlock: return "memory block";
    case ObjectKind::Texture: return "texture";
    case ObjectKind::TextureView: return "texture view";
    case ObjectKind::Sampler: return "sampler";
    case ObjectKind::ShaderModule: return "shader module";
    case ObjectKind::BindGroupLayout: return "bind group layout";
    case ObjectKind::BindGroup: return "bind group";
    case ObjectKind::ComputePipeline: return "compute pipeline";
    case ObjectKind::QuerySet: return "query set";
    case ObjectKind::CommandBuffer: return "command buffer";
    case ObjectKind::CommandEncoder: return "command encoder";
    }
    return "object";
}

int64_t LiveObjects::total() const {
    int64_t sum = 0;
    for (const int64_t c : count) sum += c;
    return sum;
}

LiveObjects liveObjects() {
    LiveObjects live;
    for (std::size_t k = 0; k < kObjectKindCount; ++k)
        live.count[k] = detail::liveCounter(ObjectKind(k)).load(std::memory_order_relaxed);
    return live;
}

} // namespace hush::rhi
