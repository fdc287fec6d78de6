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

class PushConstants;

struct TextureBarrier {
    Texture texture;
    ResourceState before = ResourceState::Undefined;
    ResourceState after = ResourceState::StorageWrite;
    // Wait for `before`'s accesses but drop the contents (old layout undefined): a
    // texture whose memory another texture used, or that is about to be overwritten.
    bool discard = false;
};

struct BufferBarrier {
    Buffer buffer;
    ResourceState before = ResourceState::Undefined;
    ResourceState after = ResourceState::StorageWrite;
};

// A barrier on all memory: what aliased memory needs when one texture's life ends
// and another's begins in the same bytes.
struct MemoryBarrier {
    ResourceState before = ResourceState::General;
    ResourceState after = ResourceState::General;
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
    // Binding a pipeline unbinds all bind groups and push constants: set them again
    // (Vulkan would keep compatible ones; hush makes every dispatch say what it reads).
    void setPipeline(const ComputePipeline& pipeline);
    void setBindGroup(uint32_t index, const BindGroup& group);
    void setPushConstants(const void* data, uint32_t bytes, uint32_t offset = 0);
    // Values written by name (push_constants.hpp): they must be for the bound pipeline
    // and complete, else hush::Error names the pipeline and the missing member.
    void setPushConstants(const PushConstants& values);
    // The raw bytes of a struct, checked for size only: for hand-written tests and
    // probes. A node's shader gets PushConstants, checked member by member.
    template <class T> void setParams(const T& params) { setPushConstants(&params, sizeof(T)); }
    void dispatchWorkgroups(uint32_t x, uint32_t y = 1, uint32_t z = 1);
    // Enough workgroups of the bound pipeline's reflected size to cover x*y*z threads.
    void dispatchThreads(uint32_t x, uint32_t y = 1, uint32_t z = 1);
    // Workgroup counts read by the device from `buffer` at `offset` (three uint32: x,
    // y, z), written there by an earlier dispatch: work whose size only the GPU knows,
    // such as the tiles a classifying pass listed. The buffer needs BufferUsage::Indirect
    // and must be in ResourceState::IndirectRead.
    void dispatchWorkgroupsIndirect(const Buffer& buffer, uint64_t offset = 0);
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
    // A reusable encoder records again after reset(), once its last command buffer's
    // submission completed, without allocating: what a render graph does every frame.
    bool reusable = false;
    // Keep every object recorded alive until the submission completes. A caller that
    // owns its objects for longer (the render graph) turns this off to record without
    // touching reference counts.
    bool trackLifetimes = true;
};

class CommandEncoder : public Handle<detail::CommandEncoderImpl> {
public:
    using Handle::Handle;

    ComputePassEncoder beginComputePass(const ComputePassDesc& desc = {});

    // One vkCmdPipelineBarrier2 for all of these.
    void barrier(std::span<const TextureBarrier> textures, std::span<const BufferBarrier> buffers = {},
                 std::span<const MemoryBarrier> memory = {});
    void barrier(std::initializer_list<TextureBarrier> textures,
                 std::initializer_list<BufferBarrier> buffers = {});
    void bufferBarrier(std::initializer_list<BufferBarrier> buffers) { barrier({}, buffers); }

    void copyBufferToBuffer(const Buffer& src, uint64_t srcOffset, const Buffer& dst,
                            uint64_t dstOffset, uint64_t size);
    // Textures must be in CopySrc / CopyDst state. size {0,0}: the whole mip.
    void copyBufferToTexture(const BufferCopyLayout& src, const TextureCopyRegion& dst, Extent2D size = {});
    void copyTextureToBuffer(const TextureCopyRegion& src, const BufferCopyLayout& dst, Extent2D size = {});
    void copyTextureToTexture(const TextureCopyRegion& src, const TextureCopyRegion& dst, Extent2D size = {});
    // offset and size (kWholeSize: to the end) must be multiples of 4.
    void fillBuffer(const Buffer& buffer, uint32_t value, uint64_t offset = 0, uint64_t size = kWholeSize);

    void resetQuerySet(const QuerySet& set, uint32_t first, uint32_t count);
    void writeTimestamp(const QuerySet& set, uint32_t index);

    CommandBuffer finish();
    // Reusable encoders only: start recording again. Throws if the last command buffer
    // is still executing (wait for its submission first).
    void reset();
};

} // namespace hush::rhi
