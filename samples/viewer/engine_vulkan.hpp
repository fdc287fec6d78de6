#pragma once
// The viewer's engine: its own Vulkan instance, device, queue, memory, images and
// buffers, made with raw Vulkan through volk. Nothing here knows hush; the
// integration layer (viewer_denoiser.hpp) takes these handles and imports them.
#include <volk.h>

#include <cstdint>
#include <string>
#include <vector>

namespace viewer {

struct EngineOptions {
    bool validation = false;                      // VK_LAYER_KHRONOS_validation with synchronization validation
    std::vector<const char*> instanceExtensions;  // e.g. the window system's surface extensions
    bool swapchain = false;                       // enable VK_KHR_swapchain on the device
    std::string adapter;                          // first adapter whose name contains this (empty: the first)
};

struct EngineImage {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    uint32_t width = 0, height = 0;
};

struct EngineBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;   // host-visible, coherent, mapped for its lifetime
    VkDeviceSize size = 0;
};

// Throws std::runtime_error naming the call when a Vulkan call fails.
void check(VkResult result, const char* what);

class EngineVulkan {
public:
    explicit EngineVulkan(const EngineOptions& options);
    ~EngineVulkan();
    EngineVulkan(const EngineVulkan&) = delete;
    EngineVulkan& operator=(const EngineVulkan&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physicalDevice() const { return physical_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queueFamily() const { return family_; }
    const std::string& adapterName() const { return adapterName_; }
    bool extendedStorageFormats() const { return extendedStorageFormats_; }
    // Validation messages seen so far (each is also printed to stderr).
    static size_t validationMessages();

    EngineImage createImage(uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage);
    void destroy(EngineImage& image);
    EngineBuffer createHostBuffer(VkDeviceSize size, VkBufferUsageFlags usage);
    void destroy(EngineBuffer& buffer);

private:
    void createInstance(const EngineOptions& options);
    void pickPhysicalDevice(const std::string& adapter);
    void createDevice(bool swapchain);
    uint32_t memoryType(uint32_t allowed, VkMemoryPropertyFlags wanted) const;
    VkDeviceMemory allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags wanted);

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t family_ = 0;
    std::string adapterName_;
    bool extendedStorageFormats_ = false;
    VkPhysicalDeviceMemoryProperties memory_{};
};

// Records an image layout transition with a full-pipeline dependency on both sides
// of the given stages/accesses (the engine's own barriers; hush plans its own).
void transition(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 srcStage,
                VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

} // namespace viewer
