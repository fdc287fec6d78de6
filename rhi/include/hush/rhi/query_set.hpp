#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <hush/rhi/handle.hpp>

namespace hush::rhi {

struct QuerySetDesc {
    std::string label;
    uint32_t count = 2;   // timestamps
};

class QuerySet : public Handle<detail::QuerySetImpl> {
public:
    using Handle::Handle;
    const std::string& label() const;
    uint32_t count() const;

    // Raw ticks of [first, first + count). Call after the submission that wrote them
    // has completed; throws if a query was never written.
    std::vector<uint64_t> readTicks(uint32_t first, uint32_t count) const;
    // The same into caller storage, without allocating (per-frame timing reads).
    void readTicks(uint32_t first, std::span<uint64_t> out) const;
    // Milliseconds between two written timestamps (end - begin).
    double elapsedMs(uint32_t beginIndex, uint32_t endIndex) const;
};

} // namespace hush::rhi
