#pragma once
// Turning VkResult into hush::Error, in one place, so every failure reads alike.
#include <string>

#include <volk.h>

#include <hush/core/error.hpp>

namespace hush::rhi::detail {

const char* vkResultName(VkResult result);

// Throws hush::Error when `result` is an error: DeviceLost for VK_ERROR_DEVICE_LOST,
// OutOfMemory for the two out-of-memory codes, Vulkan for the rest. `what` names the
// operation ("vkQueueSubmit2 for command buffer 'frame'").
void checkVk(VkResult result, const std::string& what);
// The same for a fixed description: nothing is built unless the call failed, so
// per-frame calls (submit, wait, reset) do not allocate.
inline void checkVk(VkResult result, const char* what) {
    if (result < 0) checkVk(result, std::string(what));
}

[[noreturn]] void fail(ErrorKind kind, const std::string& message);

} // namespace hush::rhi::detail
