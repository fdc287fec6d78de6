#pragma once
// A test hook: make the driver's two failures that no test machine produces on
// demand happen on the next call that could report them, so that every layer's
// handling of them can be tested (tests/rhi/test_fault_injection.cpp, the CLI's
// HUSH_INJECT_FAULT). Production code never calls it; with nothing injected the
// cost is one relaxed atomic load per device allocation and per submission.
#include <cstdint>
#include <string_view>

namespace hush::rhi {

enum class InjectedFault : uint8_t {
    None,
    // A device-memory allocation fails as with VK_ERROR_OUT_OF_DEVICE_MEMORY, once;
    // later allocations succeed again.
    OutOfDeviceMemory,
    // A queue submission fails as with VK_ERROR_DEVICE_LOST, and so does every later
    // submission and wait on that device, as on a real lost device: only a new
    // Device works again.
    DeviceLost,
};

// Arms `fault` (process-wide) to happen on the (skip + 1)-th call from now that can
// report it; None disarms. Replaces whatever was armed.
void injectFault(InjectedFault fault, uint32_t skip = 0);

// "out-of-device-memory", "device-lost" or "none" (nullopt-free: throws hush::Error
// InvalidArgument naming the text and the choices for anything else).
InjectedFault parseInjectedFault(std::string_view text);

} // namespace hush::rhi
