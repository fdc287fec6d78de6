#pragma once
// Recording: CommandEncoder -> ComputePassEncoder -> CommandBuffer (WebGPU's shape),
// plus explicit barriers, which WebGPU hides and hush's render graph decides.
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>

#include <hush/rhi/bind_group.hpp>
#include <hush/rhi/buffer.hpp>
#include <hush/rhi/pipeline.hpp>
#include <hush/rhi/query_set.hpp>
#include <hush/rhi/resource_state.hpp>
#include <hush/rhi/texture.hpp>

namespace hush::rhi {

struct TextureBarrier {
    Texture texture;
    ResourceState before = ResourceState::Undefined;
    ResourceState after = ResourceState::StorageWrite;
};

struct BufferBarrier {
    Buffer buffer;
    ResourceState before = ResourceState::Undefined;
    ResourceState after = ResourceState::StorageWrite;
};

struct TimestampWrites {
    QuerySet querySet;
    uint32_t beginIndex = 0;
    uint32_t endIndex = 1;
};

struct ComputePassDesc {
    std::string label;
    TimestampWrites timestampWrites;   // no querySet: not timed
};

struct Origin2D {
    uint32_t x = 0;
    uint32_t y = 0;
};

// A region of one texture mip; size {0,0} means the whole mip.
struct TextureCopyRegion {
    Texture texture;
    uint32_t mipLevel = 0;
    Origin2D origin;
};

struct BufferCopyLayout {
    Buffer buffer;
    uint64_t offset = 0;
    uint32_t rowLengthTexels = 0;   // 0: tightly packed
};

class ComputePassEncoder {
public:
    void setPipeline(const ComputePipeline& pipeline);
    void setBindGroup(uint32_t index, const BindGroup& group);
    void setPushConstants(const void* data, uint32_t bytes, uint32_t offset = 0);
    template <class T> void setParams(const T& params) { setPushConstants(&params, sizeof(T)); }
    void dispatchWorkgroups(uint32_t x, uint32_t y = 1, uint32_t z = 1);
    // Enough workgroups of the bound pipeline's reflected size to cover x*y*z threads.
    void dispatchThreads(uint32_t x, uint32_t y = 1, uint32_t z = 1);
    void end();

private:
    friend class CommandEncoder;
    explicit ComputePassEncoder(detail::CommandEncoderImpl* encoder) : encoder_(encoder) {}
    detail::CommandEncoderImpl* encoder_ = nullptr;
};

class CommandBuffer : public Handle<detail::CommandBufferImpl> {
public:
    using Handle::Handle;
    const std::string& label() const;
};

struct CommandEncoderDesc {
    std::string label;
};

class CommandEncoder : public Handle<detail::CommandEncoderImpl> {
public:
    using Handle::Handle;

    ComputePassEncoder beginComputePass(const ComputePassDesc& desc = {});

    // One vkCmdPipelineBarrier2 for all of these.
    void barrier(std::span<const TextureBarrier> textures, std::span<const BufferBarrier> buffers = {});
    void barrier(std::initializer_list<TextureBarrier> textures,
                 std::initializer_list<BufferBarrier> buffers = {});
    void bufferBarrier(std::initializer_list<BufferBarrier> buffers) { barrier({}, buffers); }

    void copyBufferToBuffer(const Buffer& src, uint64_t srcOffset, const Buffer& dst,
                            uint64_t dstOffset, uint64_t size);
    // Textures must be in CopySrc / CopyDst state. size {0,0}: the whole mip.
    void copyBufferToTexture(const BufferCopyLayout& src, const TextureCopyRegion& dst, Extent2D size = {});
    void copyTextureToBuffer(const TextureCopyRegion& src, const BufferCopyLayout& dst, Extent2D size = {});
    void copyTextureToTexture(const TextureCopyRegion& src, const TextureCopyRegion& dst, Extent2D size = {});
    void fillBuffer(const Buffer& buffer, uint32_t value, uint64_t offset = 0, uint64_t size = kWholeSize);

    void resetQuerySet(const QuerySet& set, uint32_t first, uint32_t count);
    void writeTimestamp(const QuerySet& set, uint32_t index);

    CommandBuffer finish();
};

} // namespace hush::rhi
