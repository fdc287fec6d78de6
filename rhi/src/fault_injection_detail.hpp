#pragma once
#include <hush/rhi/fault_injection.hpp>

namespace hush::rhi::detail {

// True when `fault` is armed and this is the call it was armed for (it is then
// disarmed); counts the call down otherwise.
bool takeInjectedFault(InjectedFault fault);

} // namespace hush::rhi::detail
