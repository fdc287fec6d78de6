#include <hush/rhi/fault_injection.hpp>

#include <atomic>
#include <string>

#include <hush/core/error.hpp>

#include "fault_injection_detail.hpp"

namespace hush::rhi {

namespace {

// One armed fault at a time: its kind in the low byte, the calls still to skip above.
std::atomic<uint64_t> armed{0};

} // namespace

void injectFault(InjectedFault fault, uint32_t skip) {
    armed.store(fault == InjectedFault::None ? 0 : (uint64_t(skip) << 8) | uint64_t(fault), std::memory_order_relaxed);
}

InjectedFault parseInjectedFault(std::string_view text) {
    if (text == "none") return InjectedFault::None;
    if (text == "out-of-device-memory") return InjectedFault::OutOfDeviceMemory;
    if (text == "device-lost") return InjectedFault::DeviceLost;
    throw Error(ErrorKind::InvalidArgument,
                "unknown fault '" + std::string(text) + "' (choices: out-of-device-memory, device-lost, none)");
}

namespace detail {

bool takeInjectedFault(InjectedFault fault) {
    uint64_t current = armed.load(std::memory_order_relaxed);
    while ((current & 0xff) == uint64_t(fault)) {
        const uint64_t skip = current >> 8;
        const uint64_t next = skip == 0 ? 0 : ((skip - 1) << 8) | uint64_t(fault);
        if (armed.compare_exchange_weak(current, next, std::memory_order_relaxed)) return skip == 0;
    }
    return false;
}

} // namespace detail

} // namespace hush::rhi
