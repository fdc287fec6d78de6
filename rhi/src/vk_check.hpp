#pragma once
// Turning VkResult into hush::Error, in one place, so every failure reads alike.
#include <string>

#include <volk.h>

#include <hush/rhi/error.hpp>

namespace hush::rhi::detail {

const char* vkResultName(VkResult result);

// Throws hush::Error when `result` is an error: DeviceLost for VK_ERROR_DEVICE_LOST,
// OutOfMemory for the two out-of-memory codes, Vulkan for the rest. `what` names the
// operation ("vkQueueSubmit2 for command buffer 'frame'").
void checkVk(VkResult result, const std::string& what);

[[noreturn]] void fail(ErrorKind kind, const std::string& message);

} // namespace hush::rhi::detail
