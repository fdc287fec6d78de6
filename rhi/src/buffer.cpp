// Buffer: device-local for GPU work, host-visible and persistently mapped for
// MapRead / MapWrite.
#include <algorithm>
#include <cstring>

#include "objects.hpp"
#include "vk_check.hpp"
#include "vk_convert.hpp"

namespace hush::rhi {
namespace detail {

BufferImpl::~BufferImpl() {
    if (!owned || buffer == VK_NULL_HANDLE) return;
    if (mapped) device->vk.vkUnmapMemory(device->device, memory);
    device->vk.vkDestroyBuffer(device->device, buffer, nullptr);
    device->free(memory, allocationBytes);
}

} // namespace detail

using namespace detail;

Buffer Device::createBuffer(const BufferDesc& desc) const {
    auto* device = checked(impl_, "Device");
    const std::string what = "buffer '" + desc.label + "'";
    if (desc.size == 0) fail(ErrorKind::InvalidArgument, what + " has size 0");
    if (desc.usage == BufferUsage::None) fail(ErrorKind::InvalidArgument, what + " has no usage");
    const bool mapRead = hasAny(desc.usage, BufferUsage::MapRead);
    const bool mapWrite = hasAny(desc.usage, BufferUsage::MapWrite);
    if (mapRead && mapWrite)
        fail(ErrorKind::InvalidArgument, what + " asks for both map-read and map-write; use two buffers");
    uint64_t largestHeap = 0;
    for (uint32_t i = 0; i < device->memory.memoryHeapCount; ++i)
        largestHeap = std::max<uint64_t>(largestHeap, device->memory.memoryHeaps[i].size);
    if (desc.size > largestHeap)
        fail(ErrorKind::OutOfMemory, what + " needs " + std::to_string(desc.size) + " bytes, more than the largest "
                                         "memory heap of '" + device->info.name + "' (" + std::to_string(largestHeap) +
                                         " bytes). Use a smaller size.");
    if (device->maxBufferSize && desc.size > device->maxBufferSize)
        fail(ErrorKind::Unsupported, what + " has " + std::to_string(desc.size) + " bytes; '" + device->info.name +
                                         "' allows at most " + std::to_string(device->maxBufferSize) + " per buffer");

    auto impl = std::make_shared<BufferImpl>();
    impl->device = impl_;
    impl->desc = desc;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = desc.size;
    info.usage = toVkBufferUsage(desc.usage);
    if (info.usage == 0) info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;   // map-only staging buffers
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    checkVk(device->vk.vkCreateBuffer(device->device, &info, nullptr, &impl->buffer), "vkCreateBuffer for " + what);

    VkMemoryRequirements req{};
    device->vk.vkGetBufferMemoryRequirements(device->device, impl->buffer, &req);
    VkMemoryPropertyFlags required = 0, preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    if (mapRead) {
        required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
        preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;   // CPU reads of uncached memory crawl
    } else if (mapWrite) {
        required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
        preferred = VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    }
    VkMemoryPropertyFlags flags = 0;
    try {
        impl->memory = device->allocate(req, required, preferred, what, &flags);
    } catch (...) {
        device->vk.vkDestroyBuffer(device->device, impl->buffer, nullptr);
        impl->buffer = VK_NULL_HANDLE;
        throw;
    }
    impl->allocationBytes = req.size;
    checkVk(device->vk.vkBindBufferMemory(device->device, impl->buffer, impl->memory, 0), "binding memory of " + what);
    if (mapRead || mapWrite) {
        checkVk(device->vk.vkMapMemory(device->device, impl->memory, 0, VK_WHOLE_SIZE, 0, &impl->mapped),
                "mapping " + what);
        impl->coherent = (flags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;
    }
    return Buffer(std::move(impl));
}

const std::string& Buffer::label() const { return checked(impl_, "Buffer")->desc.label; }
uint64_t Buffer::size() const { return checked(impl_, "Buffer")->desc.size; }
BufferUsage Buffer::usage() const { return checked(impl_, "Buffer")->desc.usage; }

void* Buffer::mappedData() const {
    auto* impl = checked(impl_, "Buffer");
    if (!impl->mapped)
        fail(ErrorKind::InvalidArgument, "buffer '" + impl->desc.label + "' is not mappable (usage " +
                                             toString(impl->desc.usage) + "); create it with MapRead or MapWrite");
    return impl->mapped;
}

namespace {
void checkRange(const BufferImpl& impl, uint64_t offset, uint64_t size, const char* op) {
    if (offset > impl.desc.size || size > impl.desc.size - offset)
        fail(ErrorKind::InvalidArgument, std::string(op) + " of " + std::to_string(size) + " bytes at offset " +
                                             std::to_string(offset) + " overruns buffer '" + impl.desc.label + "' (" +
                                             std::to_string(impl.desc.size) + " bytes)");
}

// Non-coherent memory must be flushed / invalidated on whole atoms.
VkMappedMemoryRange atomRange(const BufferImpl& impl, uint64_t offset, uint64_t size) {
    const uint64_t atom = std::max<uint64_t>(1, impl.device->limits.nonCoherentAtomSize);
    VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
    range.memory = impl.memory;
    range.offset = offset / atom * atom;
    const uint64_t end = (offset + size + atom - 1) / atom * atom;
    range.size = std::min(end, impl.allocationBytes) - range.offset;
    return range;
}
} // namespace

void Buffer::write(std::span<const std::byte> bytes, uint64_t offset) const {
    auto* impl = checked(impl_, "Buffer");
    auto* base = static_cast<std::byte*>(mappedData());
    checkRange(*impl, offset, bytes.size(), "write");
    std::memcpy(base + offset, bytes.data(), bytes.size());
    if (!impl->coherent) {
        auto range = atomRange(*impl, offset, bytes.size());
        checkVk(impl->device->vk.vkFlushMappedMemoryRanges(impl->device->device, 1, &range), "flushing a mapped buffer");
    }
}

void Buffer::read(std::span<std::byte> out, uint64_t offset) const {
    auto* impl = checked(impl_, "Buffer");
    auto* base = static_cast<const std::byte*>(mappedData());
    checkRange(*impl, offset, out.size(), "read");
    if (!impl->coherent) {
        auto range = atomRange(*impl, offset, out.size());
        checkVk(impl->device->vk.vkInvalidateMappedMemoryRanges(impl->device->device, 1, &range),
                "invalidating a mapped buffer");
    }
    std::memcpy(out.data(), base + offset, out.size());
}

} // namespace hush::rhi
