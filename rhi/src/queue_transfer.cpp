// WebGPU-style queue.writeBuffer / writeTexture and their read-back twins, done
// through a staging buffer and a wait. For setup, tests and tools, not per frame.
#include <algorithm>
#include <cstring>

#include "objects.hpp"
#include "vk_check.hpp"

namespace hush::rhi {

using namespace detail;

namespace {

Device deviceOf(const std::shared_ptr<DeviceImpl>& impl) { return Device(impl); }

// Whatever came before, everything after sees it: staging copies are rare and
// waited on, so a full barrier costs nothing worth saving.
void fullBarrier(CommandEncoder& enc, const Buffer& buffer) {
    enc.bufferBarrier({{buffer, ResourceState::General, ResourceState::General}});
}

Extent2D resolveSize(const Texture& texture, uint32_t mip, Origin2D origin, Extent2D size) {
    if (size.width || size.height) return size;
    const uint32_t w = std::max(1u, texture.width() >> mip), h = std::max(1u, texture.height() >> mip);
    return {w - std::min(w, origin.x), h - std::min(h, origin.y)};
}

} // namespace

void Queue::writeBuffer(const Buffer& buffer, uint64_t offset, std::span<const std::byte> data) {
    checked(buffer.shared(), "Buffer");
    if (data.empty()) return;
    auto device = deviceOf(device_);
    auto staging = device.createBuffer({.label = buffer.label() + ".staging", .size = data.size(),
                                        .usage = BufferUsage::MapWrite | BufferUsage::CopySrc});
    staging.write(data);
    auto enc = device.createCommandEncoder({.label = "writeBuffer(" + buffer.label() + ")"});
    fullBarrier(enc, buffer);
    enc.copyBufferToBuffer(staging, 0, buffer, offset, data.size());
    fullBarrier(enc, buffer);
    wait(submit(enc.finish()));
}

std::vector<std::byte> Queue::readBuffer(const Buffer& buffer, uint64_t offset, uint64_t size) {
    checked(buffer.shared(), "Buffer");
    if (size == kWholeSize) size = buffer.size() - std::min(offset, buffer.size());
    auto device = deviceOf(device_);
    auto staging = device.createBuffer({.label = buffer.label() + ".readback", .size = std::max<uint64_t>(size, 4),
                                        .usage = BufferUsage::MapRead | BufferUsage::CopyDst});
    auto enc = device.createCommandEncoder({.label = "readBuffer(" + buffer.label() + ")"});
    fullBarrier(enc, buffer);
    enc.copyBufferToBuffer(buffer, offset, staging, 0, size);
    enc.bufferBarrier({{staging, ResourceState::CopyDst, ResourceState::HostRead}});
    wait(submit(enc.finish()));
    std::vector<std::byte> out(size);
    staging.read(out);
    return out;
}

void Queue::writeTexture(const TextureWrite& w) {
    checked(w.texture.shared(), "Texture");
    if (w.after == ResourceState::Undefined)
        fail(ErrorKind::InvalidArgument, "writeTexture to '" + w.texture.label() + "': 'after' must not be undefined");
    const auto size = resolveSize(w.texture, w.mipLevel, w.origin, w.size);
    const uint64_t bytes = uint64_t(size.width) * size.height * formatInfo(w.texture.format()).bytesPerPixel;
    if (w.data.size() != bytes)
        fail(ErrorKind::InvalidArgument, "writeTexture to '" + w.texture.label() + "': " + std::to_string(w.data.size()) +
                                             " bytes given, a " + std::to_string(size.width) + "x" +
                                             std::to_string(size.height) + " " +
                                             std::string(toString(w.texture.format())) + " region needs " +
                                             std::to_string(bytes));
    auto device = deviceOf(device_);
    auto staging = device.createBuffer({.label = w.texture.label() + ".staging", .size = bytes,
                                        .usage = BufferUsage::MapWrite | BufferUsage::CopySrc});
    staging.write(w.data);
    auto enc = device.createCommandEncoder({.label = "writeTexture(" + w.texture.label() + ")"});
    enc.barrier({{w.texture, w.before, ResourceState::CopyDst}});
    enc.copyBufferToTexture({.buffer = staging}, {.texture = w.texture, .mipLevel = w.mipLevel, .origin = w.origin}, size);
    enc.barrier({{w.texture, ResourceState::CopyDst, w.after}});
    wait(submit(enc.finish()));
}

std::vector<std::byte> Queue::readTexture(const TextureRead& r) {
    checked(r.texture.shared(), "Texture");
    if (r.state == ResourceState::Undefined)
        fail(ErrorKind::InvalidArgument, "readTexture of '" + r.texture.label() +
                                             "' in state undefined: it has no defined contents to read");
    const auto size = resolveSize(r.texture, r.mipLevel, r.origin, r.size);
    const uint64_t bytes = uint64_t(size.width) * size.height * formatInfo(r.texture.format()).bytesPerPixel;
    auto device = deviceOf(device_);
    auto staging = device.createBuffer({.label = r.texture.label() + ".readback", .size = bytes,
                                        .usage = BufferUsage::MapRead | BufferUsage::CopyDst});
    auto enc = device.createCommandEncoder({.label = "readTexture(" + r.texture.label() + ")"});
    enc.barrier({{r.texture, r.state, ResourceState::CopySrc}});
    enc.copyTextureToBuffer({.texture = r.texture, .mipLevel = r.mipLevel, .origin = r.origin}, {.buffer = staging}, size);
    enc.barrier({{r.texture, ResourceState::CopySrc, r.state}},
                {{staging, ResourceState::CopyDst, ResourceState::HostRead}});
    wait(submit(enc.finish()));
    std::vector<std::byte> out(bytes);
    staging.read(out);
    return out;
}

} // namespace hush::rhi
