#include "vk_check.hpp"

namespace hush::rhi::detail {

const char* vkResultName(VkResult result) {
    switch (result) {
    case VK_SUCCESS: return "VK_SUCCESS";
    case VK_NOT_READY: return "VK_NOT_READY";
    case VK_TIMEOUT: return "VK_TIMEOUT";
    case VK_INCOMPLETE: return "VK_INCOMPLETE";
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_MEMORY_MAP_FAILED: return "VK_ERROR_MEMORY_MAP_FAILED";
    case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_TOO_MANY_OBJECTS: return "VK_ERROR_TOO_MANY_OBJECTS";
    case VK_ERROR_FORMAT_NOT_SUPPORTED: return "VK_ERROR_FORMAT_NOT_SUPPORTED";
    case VK_ERROR_FRAGMENTED_POOL: return "VK_ERROR_FRAGMENTED_POOL";
    case VK_ERROR_OUT_OF_POOL_MEMORY: return "VK_ERROR_OUT_OF_POOL_MEMORY";
    case VK_ERROR_UNKNOWN: return "VK_ERROR_UNKNOWN";
    default: return "VkResult(other)";
    }
}

void fail(ErrorKind kind, const std::string& message) { throw Error(kind, message); }

void checkVk(VkResult result, const std::string& what) {
    if (result >= 0) return;
    std::string code = vkResultName(result);
    if (code == "VkResult(other)") code = "VkResult " + std::to_string(int(result));
    switch (result) {
    case VK_ERROR_DEVICE_LOST:
        fail(ErrorKind::DeviceLost, what + " failed: the GPU device was lost (" + code +
                                        "). The driver reset or crashed; recreate the Device and its resources.");
    case VK_ERROR_OUT_OF_DEVICE_MEMORY:
        fail(ErrorKind::OutOfMemory, what + " failed: out of device memory (" + code +
                                         "). Use smaller images or fewer frames in flight.");
    case VK_ERROR_OUT_OF_HOST_MEMORY:
        fail(ErrorKind::OutOfMemory, what + " failed: out of host memory (" + code + ").");
    default:
        fail(ErrorKind::Driver, what + " failed with " + code + ".");
    }
}

} // namespace hush::rhi::detail
