#pragma once
// A stand-in for an engine's own Vulkan setup, for the interop tests: a raw
// VkInstance with the validation layer and synchronization validation (its messages
// go to the tests' validation log), a Vulkan 1.3 VkDevice with timelineSemaphore and
// synchronization2, its VkQueue, a host-visible VkBuffer, a VkImage, and a command
// buffer the "engine" submits itself. The destructor destroys all of it, in reverse.
//
// Loading: volkInitialize() opens the loader; every raw instance and device function
// is then fetched into this struct with vkGetInstanceProcAddr / vkGetDeviceProcAddr
// instead of volkLoadInstance / volkLoadDevice, which would overwrite volk's
// process-wide pointers that the shared test device also relies on.
#include <volk.h>

#include <cstdint>
#include <string>
#include <vector>

namespace hush::test {

#define HUSH_RAW_FN(name) PFN_##name name = nullptr

// The engine: raw Vulkan objects, destroyed in reverse order by the destructor.
struct RawVulkan {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t family = ~0u;
    std::string name;
    VkPhysicalDeviceMemoryProperties memoryProps{};

    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory bufferMemory = VK_NULL_HANDLE;
    void* mapped = nullptr;
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory imageMemory = VK_NULL_HANDLE;
    VkCommandPool pool = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;

    HUSH_RAW_FN(vkDestroyInstance);
    HUSH_RAW_FN(vkEnumeratePhysicalDevices);
    HUSH_RAW_FN(vkGetPhysicalDeviceProperties);
    HUSH_RAW_FN(vkGetPhysicalDeviceQueueFamilyProperties);
    HUSH_RAW_FN(vkGetPhysicalDeviceMemoryProperties);
    HUSH_RAW_FN(vkCreateDevice);
    HUSH_RAW_FN(vkGetDeviceProcAddr);
    HUSH_RAW_FN(vkCreateDebugUtilsMessengerEXT);
    HUSH_RAW_FN(vkDestroyDebugUtilsMessengerEXT);
    HUSH_RAW_FN(vkDestroyDevice);
    HUSH_RAW_FN(vkDeviceWaitIdle);
    HUSH_RAW_FN(vkGetDeviceQueue);
    HUSH_RAW_FN(vkCreateBuffer);
    HUSH_RAW_FN(vkDestroyBuffer);
    HUSH_RAW_FN(vkGetBufferMemoryRequirements);
    HUSH_RAW_FN(vkBindBufferMemory);
    HUSH_RAW_FN(vkCreateImage);
    HUSH_RAW_FN(vkDestroyImage);
    HUSH_RAW_FN(vkGetImageMemoryRequirements);
    HUSH_RAW_FN(vkBindImageMemory);
    HUSH_RAW_FN(vkAllocateMemory);
    HUSH_RAW_FN(vkFreeMemory);
    HUSH_RAW_FN(vkMapMemory);
    HUSH_RAW_FN(vkUnmapMemory);
    HUSH_RAW_FN(vkCreateCommandPool);
    HUSH_RAW_FN(vkDestroyCommandPool);
    HUSH_RAW_FN(vkAllocateCommandBuffers);
    HUSH_RAW_FN(vkBeginCommandBuffer);
    HUSH_RAW_FN(vkEndCommandBuffer);
    HUSH_RAW_FN(vkQueueSubmit);
    HUSH_RAW_FN(vkCreateFence);
    HUSH_RAW_FN(vkDestroyFence);
    HUSH_RAW_FN(vkWaitForFences);
    HUSH_RAW_FN(vkCmdPipelineBarrier);
    HUSH_RAW_FN(vkCmdCopyBufferToImage);

    RawVulkan() = default;
    RawVulkan(const RawVulkan&) = delete;
    RawVulkan& operator=(const RawVulkan&) = delete;

    ~RawVulkan();

    // Each step REQUIREs success. Call in this order: instance, physical device, device,
    // then the objects.
    void createInstance();
    // The adapter HUSH_ADAPTER names (CTest: llvmpipe), else the first with a compute queue.
    void pickPhysicalDevice();
    void createDevice();
    uint32_t memoryType(uint32_t allowed, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) const;
    void createBuffer(VkDeviceSize size);
    void createImage(uint32_t width, uint32_t height);
    // A begun one-time command buffer, and the fence its submission will signal.
    VkCommandBuffer beginCommands();
    void submitAndWait(VkCommandBuffer cmd);
    // The buffer's first `count` uint32 values, through the engine's own mapping.
    std::vector<uint32_t> mappedValues(size_t count) const;

private:
    template <class F> void loadInstanceFn(F& fn, const char* fnName);
    template <class F> void loadDeviceFn(F& fn, const char* fnName);
};

#undef HUSH_RAW_FN

} // namespace hush::test
