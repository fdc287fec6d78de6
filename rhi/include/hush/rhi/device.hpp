#pragma once
// Device and Queue. The Device creates every object; the Queue submits command
// buffers and offers the upload / read-back conveniences of WebGPU's queue.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <hush/rhi/bind_group.hpp>
#include <hush/rhi/buffer.hpp>
#include <hush/rhi/command.hpp>
#include <hush/rhi/instance.hpp>
#include <hush/rhi/memory_block.hpp>
#include <hush/rhi/pipeline.hpp>
#include <hush/rhi/query_set.hpp>
#include <hush/rhi/resource_state.hpp>
#include <hush/rhi/shader.hpp>
#include <hush/rhi/texture.hpp>

namespace hush::rhi {

struct DeviceDesc {
    std::string label = "hush";
};

// A point in the queue's timeline: submissions complete in order.
using SubmissionId = uint64_t;

struct TextureWrite {
    Texture texture;
    std::span<const std::byte> data;   // tightly packed rows of `size` texels
    uint32_t mipLevel = 0;
    Origin2D origin;
    Extent2D size;                      // {0,0}: the whole mip
    ResourceState before = ResourceState::Undefined;
    ResourceState after = ResourceState::SampledRead;
};

struct TextureRead {
    Texture texture;
    uint32_t mipLevel = 0;
    Origin2D origin;
    Extent2D size;                      // {0,0}: the whole mip
    ResourceState state = ResourceState::SampledRead;   // current, and restored after
};

class Queue {
public:
    SubmissionId submit(const CommandBuffer& commands);
    SubmissionId submit(std::span<const CommandBuffer> commands);
    // Blocks until `id` completed; throws hush::Error (DeviceLost) if the device died.
    void wait(SubmissionId id);
    void waitIdle();
    bool isComplete(SubmissionId id) const;
    SubmissionId lastSubmitted() const;

    // Upload / read back through a staging buffer, waiting for completion. Meant for
    // tests, tools and setup, not for per-frame work. The buffer versions wait for all
    // earlier work and make the data visible to all later work (treat the buffer as in
    // state General afterwards); the texture versions move between the states given.
    void writeBuffer(const Buffer& buffer, uint64_t offset, std::span<const std::byte> data);
    std::vector<std::byte> readBuffer(const Buffer& buffer, uint64_t offset = 0, uint64_t size = kWholeSize);
    void writeTexture(const TextureWrite& write);
    std::vector<std::byte> readTexture(const TextureRead& read);

private:
    friend class Device;
    explicit Queue(std::shared_ptr<detail::DeviceImpl> device) : device_(std::move(device)) {}
    std::shared_ptr<detail::DeviceImpl> device_;
};

class Device : public Handle<detail::DeviceImpl> {
public:
    using Handle::Handle;

    const AdapterInfo& adapterInfo() const;
    Queue queue() const;

    Buffer createBuffer(const BufferDesc& desc) const;
    Texture createTexture(const TextureDesc& desc) const;
    // A texture placed at `offset` in `block`, sharing it with others (memory
    // aliasing). Textures whose lifetimes overlap must not overlap in the block.
    Texture createTexture(const TextureDesc& desc, const MemoryBlock& block, uint64_t offset) const;
    // What a texture of `desc` needs, without creating it.
    MemoryRequirements textureMemoryRequirements(const TextureDesc& desc) const;
    MemoryBlock createMemoryBlock(const MemoryBlockDesc& desc) const;
    Sampler createSampler(const SamplerDesc& desc = {}) const;
    ShaderModule createShaderModule(const ShaderModuleDesc& desc) const;
    BindGroupLayout createBindGroupLayout(const BindGroupLayoutDesc& desc) const;
    BindGroup createBindGroup(const BindGroupDesc& desc) const;
    ComputePipeline createComputePipeline(const ComputePipelineDesc& desc) const;
    CommandEncoder createCommandEncoder(const CommandEncoderDesc& desc = {}) const;
    QuerySet createQuerySet(const QuerySetDesc& desc) const;

    // Bytes of device memory hush has allocated and not yet freed.
    uint64_t allocatedBytes() const;
    void waitIdle() const;
};

} // namespace hush::rhi
