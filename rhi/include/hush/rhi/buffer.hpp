#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <hush/rhi/format.hpp>
#include <hush/rhi/handle.hpp>

namespace hush::rhi {

inline constexpr uint64_t kWholeSize = ~0ull;

struct BufferDesc {
    std::string label;
    uint64_t size = 0;
    BufferUsage usage = BufferUsage::Storage;
};

class Buffer : public Handle<detail::BufferImpl> {
public:
    using Handle::Handle;

    const std::string& label() const;
    uint64_t size() const;
    BufferUsage usage() const;

    // Host access, only for MapRead / MapWrite buffers (persistently mapped).
    // The caller orders these against the GPU (wait for the submission first).
    void* mappedData() const;
    void write(std::span<const std::byte> bytes, uint64_t offset = 0) const;
    void read(std::span<std::byte> out, uint64_t offset = 0) const;
    template <class T> void writeValues(std::span<const T> values, uint64_t offset = 0) const {
        write(std::as_bytes(values), offset);
    }
    template <class T> std::vector<T> readValues(size_t count, uint64_t offset = 0) const {
        std::vector<T> out(count);
        read(std::as_writable_bytes(std::span<T>(out)), offset);
        return out;
    }
};

} // namespace hush::rhi
