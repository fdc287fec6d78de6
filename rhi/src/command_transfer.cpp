// The CommandEncoder's barriers and copies.
#include <algorithm>
#include <vector>

#include "objects.hpp"
#include "vk_check.hpp"
#include "vk_convert.hpp"

namespace hush::rhi {

using namespace detail;

namespace {

Extent2D mipExtent(const TextureImpl& t, uint32_t mip) {
    return {std::max(1u, t.desc.size.width >> mip), std::max(1u, t.desc.size.height >> mip)};
}

// Resolves a region's size ({0,0}: rest of the mip) and checks it lies inside the mip.
Extent2D checkRegion(const TextureCopyRegion& r, Extent2D size, const char* op) {
    auto* t = checked(r.texture.shared(), "Texture");
    if (r.mipLevel >= t->desc.mipLevelCount)
        fail(ErrorKind::InvalidArgument, std::string(op) + ": texture '" + t->desc.label + "' has no mip " +
                                             std::to_string(r.mipLevel));
    const auto mip = mipExtent(*t, r.mipLevel);
    if (size.width == 0 && size.height == 0)
        size = {mip.width - std::min(mip.width, r.origin.x), mip.height - std::min(mip.height, r.origin.y)};
    if (size.width == 0 || size.height == 0 || r.origin.x + size.width > mip.width || r.origin.y + size.height > mip.height)
        fail(ErrorKind::InvalidArgument, std::string(op) + ": region " + std::to_string(size.width) + "x" +
                                             std::to_string(size.height) + " at (" + std::to_string(r.origin.x) + "," +
                                             std::to_string(r.origin.y) + ") is outside mip " +
                                             std::to_string(r.mipLevel) + " of texture '" + t->desc.label + "' (" +
                                             std::to_string(mip.width) + "x" + std::to_string(mip.height) + ")");
    return size;
}

void requireUsage(const Texture& t, TextureUsage usage, const char* op) {
    if (!hasAny(t.usage(), usage))
        fail(ErrorKind::InvalidArgument, std::string(op) + ": texture '" + t.label() + "' lacks usage " + toString(usage));
}

void requireUsage(const Buffer& b, BufferUsage usage, const char* op) {
    if (!hasAny(checked(b.shared(), "Buffer")->desc.usage, usage))
        fail(ErrorKind::InvalidArgument, std::string(op) + ": buffer '" + b.label() + "' lacks usage " + toString(usage));
}

VkBufferImageCopy bufferImageCopy(const BufferCopyLayout& b, const TextureCopyRegion& t, Extent2D size,
                                  const char* op) {
    const auto texel = formatInfo(t.texture.format()).bytesPerPixel;
    const uint64_t row = b.rowLengthTexels ? b.rowLengthTexels : size.width;
    if (row < size.width)
        fail(ErrorKind::InvalidArgument, std::string(op) + ": rowLengthTexels " + std::to_string(row) +
                                             " is less than the copy width " + std::to_string(size.width));
    const uint64_t bytes = (row * (size.height - 1) + size.width) * texel;
    if (b.offset % texel || b.offset + bytes > b.buffer.size())
        fail(ErrorKind::InvalidArgument, std::string(op) + ": " + std::to_string(bytes) + " bytes at offset " +
                                             std::to_string(b.offset) + " do not fit buffer '" + b.buffer.label() +
                                             "' (" + std::to_string(b.buffer.size()) + " bytes, offset aligned to " +
                                             std::to_string(texel) + ")");
    VkBufferImageCopy copy{};
    copy.bufferOffset = b.offset;
    copy.bufferRowLength = b.rowLengthTexels;
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, t.mipLevel, 0, 1};
    copy.imageOffset = {int32_t(t.origin.x), int32_t(t.origin.y), 0};
    copy.imageExtent = {size.width, size.height, 1};
    return copy;
}

} // namespace

void CommandEncoder::barrier(std::initializer_list<TextureBarrier> textures, std::initializer_list<BufferBarrier> buffers) {
    barrier(std::span<const TextureBarrier>(textures.begin(), textures.size()),
            std::span<const BufferBarrier>(buffers.begin(), buffers.size()));
}

void CommandEncoder::barrier(std::span<const TextureBarrier> textures, std::span<const BufferBarrier> buffers,
                             std::span<const MemoryBarrier> memory) {
    auto* enc = checked(impl_, "CommandEncoder");
    enc->requireOutsidePass("barrier");
    auto& images = enc->imageBarriers;
    auto& bufs = enc->bufferBarriers;
    auto& globals = enc->memoryBarriers;
    images.clear();
    bufs.clear();
    globals.clear();
    for (const auto& b : textures) {
        const auto& t = b.texture.shared();
        checked(t, "Texture");
        if (b.after == ResourceState::Undefined)
            fail(ErrorKind::InvalidArgument, "barrier on texture '" + t->desc.label + "' to state undefined");
        const auto src = toVk(b.before), dst = toVk(b.after);
        VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        barrier.srcStageMask = src.stages;
        barrier.srcAccessMask = src.access;
        barrier.dstStageMask = dst.stages;
        barrier.dstAccessMask = dst.access;
        barrier.oldLayout = b.discard ? VK_IMAGE_LAYOUT_UNDEFINED : src.layout;
        barrier.newLayout = dst.layout;
        barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.image = t->image;
        barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0, 1};
        images.push_back(barrier);
        enc->retain(t);
    }
    for (const auto& b : buffers) {
        const auto& buf = b.buffer.shared();
        checked(buf, "Buffer");
        const auto src = toVk(b.before), dst = toVk(b.after);
        VkBufferMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
        barrier.srcStageMask = src.stages;
        barrier.srcAccessMask = src.access;
        barrier.dstStageMask = dst.stages;
        barrier.dstAccessMask = dst.access;
        barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.buffer = buf->buffer;
        barrier.offset = 0;
        barrier.size = VK_WHOLE_SIZE;
        bufs.push_back(barrier);
        enc->retain(buf);
    }
    for (const auto& m : memory) {
        const auto src = toVk(m.before), dst = toVk(m.after);
        VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
        barrier.srcStageMask = src.stages;
        barrier.srcAccessMask = src.access;
        barrier.dstStageMask = dst.stages;
        barrier.dstAccessMask = dst.access;
        globals.push_back(barrier);
    }
    if (images.empty() && bufs.empty() && globals.empty()) return;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = uint32_t(globals.size());
    dep.pMemoryBarriers = globals.data();
    dep.imageMemoryBarrierCount = uint32_t(images.size());
    dep.pImageMemoryBarriers = images.data();
    dep.bufferMemoryBarrierCount = uint32_t(bufs.size());
    dep.pBufferMemoryBarriers = bufs.data();
    enc->device->vk.vkCmdPipelineBarrier2(enc->commandBuffer, &dep);
}

void CommandEncoder::copyBufferToBuffer(const Buffer& src, uint64_t srcOffset, const Buffer& dst, uint64_t dstOffset,
                                        uint64_t size) {
    auto* enc = checked(impl_, "CommandEncoder");
    enc->requireOutsidePass("copyBufferToBuffer");
    requireUsage(src, BufferUsage::CopySrc, "copyBufferToBuffer");
    requireUsage(dst, BufferUsage::CopyDst, "copyBufferToBuffer");
    if (size == 0 || srcOffset + size > src.size() || dstOffset + size > dst.size())
        fail(ErrorKind::InvalidArgument, "copyBufferToBuffer of " + std::to_string(size) + " bytes from '" + src.label() +
                                             "'+" + std::to_string(srcOffset) + " to '" + dst.label() + "'+" +
                                             std::to_string(dstOffset) + " is out of range");
    VkBufferCopy region{srcOffset, dstOffset, size};
    enc->device->vk.vkCmdCopyBuffer(enc->commandBuffer, src.impl()->buffer, dst.impl()->buffer, 1, &region);
    enc->retain(src.shared());
    enc->retain(dst.shared());
}

void CommandEncoder::copyBufferToTexture(const BufferCopyLayout& src, const TextureCopyRegion& dst, Extent2D size) {
    auto* enc = checked(impl_, "CommandEncoder");
    enc->requireOutsidePass("copyBufferToTexture");
    size = checkRegion(dst, size, "copyBufferToTexture");
    requireUsage(src.buffer, BufferUsage::CopySrc, "copyBufferToTexture");
    requireUsage(dst.texture, TextureUsage::CopyDst, "copyBufferToTexture");
    const auto copy = bufferImageCopy(src, dst, size, "copyBufferToTexture");
    enc->device->vk.vkCmdCopyBufferToImage(enc->commandBuffer, src.buffer.impl()->buffer, dst.texture.impl()->image,
                                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
    enc->retain(src.buffer.shared());
    enc->retain(dst.texture.shared());
}

void CommandEncoder::copyTextureToBuffer(const TextureCopyRegion& src, const BufferCopyLayout& dst, Extent2D size) {
    auto* enc = checked(impl_, "CommandEncoder");
    enc->requireOutsidePass("copyTextureToBuffer");
    size = checkRegion(src, size, "copyTextureToBuffer");
    requireUsage(src.texture, TextureUsage::CopySrc, "copyTextureToBuffer");
    requireUsage(dst.buffer, BufferUsage::CopyDst, "copyTextureToBuffer");
    const auto copy = bufferImageCopy(dst, src, size, "copyTextureToBuffer");
    enc->device->vk.vkCmdCopyImageToBuffer(enc->commandBuffer, src.texture.impl()->image,
                                           VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst.buffer.impl()->buffer, 1, &copy);
    enc->retain(src.texture.shared());
    enc->retain(dst.buffer.shared());
}

void CommandEncoder::copyTextureToTexture(const TextureCopyRegion& src, const TextureCopyRegion& dst, Extent2D size) {
    auto* enc = checked(impl_, "CommandEncoder");
    enc->requireOutsidePass("copyTextureToTexture");
    size = checkRegion(src, size, "copyTextureToTexture");
    checkRegion(dst, size, "copyTextureToTexture");
    requireUsage(src.texture, TextureUsage::CopySrc, "copyTextureToTexture");
    requireUsage(dst.texture, TextureUsage::CopyDst, "copyTextureToTexture");
    if (formatInfo(src.texture.format()).bytesPerPixel != formatInfo(dst.texture.format()).bytesPerPixel)
        fail(ErrorKind::InvalidArgument, "copyTextureToTexture from '" + src.texture.label() + "' (" +
                                             std::string(toString(src.texture.format())) + ") to '" +
                                             dst.texture.label() + "' (" + std::string(toString(dst.texture.format())) +
                                             "): texel sizes differ");
    VkImageCopy copy{};
    copy.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, src.mipLevel, 0, 1};
    copy.srcOffset = {int32_t(src.origin.x), int32_t(src.origin.y), 0};
    copy.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, dst.mipLevel, 0, 1};
    copy.dstOffset = {int32_t(dst.origin.x), int32_t(dst.origin.y), 0};
    copy.extent = {size.width, size.height, 1};
    enc->device->vk.vkCmdCopyImage(enc->commandBuffer, src.texture.impl()->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                   dst.texture.impl()->image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
    enc->retain(src.texture.shared());
    enc->retain(dst.texture.shared());
}

void CommandEncoder::fillBuffer(const Buffer& buffer, uint32_t value, uint64_t offset, uint64_t size) {
    auto* enc = checked(impl_, "CommandEncoder");
    enc->requireOutsidePass("fillBuffer");
    requireUsage(buffer, BufferUsage::CopyDst, "fillBuffer");
    if (size == kWholeSize) size = buffer.size() - std::min(offset, buffer.size());
    if (offset % 4 || size % 4 || size == 0 || offset + size > buffer.size())
        fail(ErrorKind::InvalidArgument, "fillBuffer of '" + buffer.label() + "': range [" + std::to_string(offset) +
                                             ", +" + std::to_string(size) + ") must be 4-byte aligned and inside the buffer");
    enc->device->vk.vkCmdFillBuffer(enc->commandBuffer, buffer.impl()->buffer, offset, size, value);
    enc->retain(buffer.shared());
}

} // namespace hush::rhi
