#include "support/raw_vulkan.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>

#include "support/gpu_context.hpp"

namespace hush::test {

namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL onRawMessage(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                            const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    recordValidationMessage(std::string("[raw instance] ") + (data && data->pMessage ? data->pMessage : "(none)"));
    return VK_FALSE;
}

} // namespace

RawVulkan::~RawVulkan() {
    if (device && vkDestroyDevice) {   // (functions are null if a step failed before loading them)
        vkDeviceWaitIdle(device);
        if (fence) vkDestroyFence(device, fence, nullptr);
        if (pool) vkDestroyCommandPool(device, pool, nullptr);
        if (image) vkDestroyImage(device, image, nullptr);
        if (imageMemory) vkFreeMemory(device, imageMemory, nullptr);
        if (mapped) vkUnmapMemory(device, bufferMemory);
        if (buffer) vkDestroyBuffer(device, buffer, nullptr);
        if (bufferMemory) vkFreeMemory(device, bufferMemory, nullptr);
        vkDestroyDevice(device, nullptr);
    }
    if (messenger && vkDestroyDebugUtilsMessengerEXT) vkDestroyDebugUtilsMessengerEXT(instance, messenger, nullptr);
    if (instance && vkDestroyInstance) vkDestroyInstance(instance, nullptr);
}

template <class F> void RawVulkan::loadInstanceFn(F& fn, const char* fnName) {
    fn = reinterpret_cast<F>(vkGetInstanceProcAddr(instance, fnName));
    INFO(fnName);
    REQUIRE(fn != nullptr);
}
template <class F> void RawVulkan::loadDeviceFn(F& fn, const char* fnName) {
    fn = reinterpret_cast<F>(vkGetDeviceProcAddr(device, fnName));
    INFO(fnName);
    REQUIRE(fn != nullptr);
}

void RawVulkan::createInstance() {
    REQUIRE(volkInitialize() == VK_SUCCESS);
    const char* layers[] = {"VK_LAYER_KHRONOS_validation"};
    const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME};
    const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = onRawMessage;
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.pNext = &messengerInfo;
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enables;
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "raw engine";
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pNext = &features;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = layers;
    info.enabledExtensionCount = 2;
    info.ppEnabledExtensionNames = extensions;
    REQUIRE(vkCreateInstance(&info, nullptr, &instance) == VK_SUCCESS);

    loadInstanceFn(vkDestroyInstance, "vkDestroyInstance");
    loadInstanceFn(vkCreateDebugUtilsMessengerEXT, "vkCreateDebugUtilsMessengerEXT");
    loadInstanceFn(vkDestroyDebugUtilsMessengerEXT, "vkDestroyDebugUtilsMessengerEXT");
    REQUIRE(vkCreateDebugUtilsMessengerEXT(instance, &messengerInfo, nullptr, &messenger) == VK_SUCCESS);
    loadInstanceFn(vkEnumeratePhysicalDevices, "vkEnumeratePhysicalDevices");
    loadInstanceFn(vkGetPhysicalDeviceProperties, "vkGetPhysicalDeviceProperties");
    loadInstanceFn(vkGetPhysicalDeviceQueueFamilyProperties, "vkGetPhysicalDeviceQueueFamilyProperties");
    loadInstanceFn(vkGetPhysicalDeviceMemoryProperties, "vkGetPhysicalDeviceMemoryProperties");
    loadInstanceFn(vkCreateDevice, "vkCreateDevice");
    loadInstanceFn(vkGetDeviceProcAddr, "vkGetDeviceProcAddr");
}

void RawVulkan::pickPhysicalDevice() {
    uint32_t count = 0;
    REQUIRE(vkEnumeratePhysicalDevices(instance, &count, nullptr) == VK_SUCCESS);
    std::vector<VkPhysicalDevice> all(count);
    REQUIRE(vkEnumeratePhysicalDevices(instance, &count, all.data()) == VK_SUCCESS);
    const char* wanted = std::getenv("HUSH_ADAPTER");
    for (auto candidate : all) {
        VkPhysicalDeviceProperties props{};
        vkGetPhysicalDeviceProperties(candidate, &props);
        if (props.apiVersion < VK_API_VERSION_1_3) continue;
        if (wanted && *wanted && !std::strstr(props.deviceName, wanted)) continue;
        uint32_t familyCount = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(candidate, &familyCount, nullptr);
        std::vector<VkQueueFamilyProperties> families(familyCount);
        vkGetPhysicalDeviceQueueFamilyProperties(candidate, &familyCount, families.data());
        for (uint32_t i = 0; i < familyCount; ++i) {
            if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
                physical = candidate;
                family = i;
                name = props.deviceName;
                vkGetPhysicalDeviceMemoryProperties(candidate, &memoryProps);
                return;
            }
        }
    }
    FAIL("no Vulkan 1.3 physical device with a compute queue" << (wanted ? " matching HUSH_ADAPTER" : ""));
}

void RawVulkan::createDevice() {
    VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    features13.synchronization2 = VK_TRUE;
    VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    features12.pNext = &features13;
    features12.timelineSemaphore = VK_TRUE;
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features.pNext = &features12;
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = family;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = &features;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    REQUIRE(vkCreateDevice(physical, &info, nullptr, &device) == VK_SUCCESS);
#define HUSH_LOAD_DEVICE(fn) loadDeviceFn(fn, #fn)
    HUSH_LOAD_DEVICE(vkDestroyDevice);
    HUSH_LOAD_DEVICE(vkDeviceWaitIdle);
    HUSH_LOAD_DEVICE(vkGetDeviceQueue);
    HUSH_LOAD_DEVICE(vkCreateBuffer);
    HUSH_LOAD_DEVICE(vkDestroyBuffer);
    HUSH_LOAD_DEVICE(vkGetBufferMemoryRequirements);
    HUSH_LOAD_DEVICE(vkBindBufferMemory);
    HUSH_LOAD_DEVICE(vkCreateImage);
    HUSH_LOAD_DEVICE(vkDestroyImage);
    HUSH_LOAD_DEVICE(vkGetImageMemoryRequirements);
    HUSH_LOAD_DEVICE(vkBindImageMemory);
    HUSH_LOAD_DEVICE(vkAllocateMemory);
    HUSH_LOAD_DEVICE(vkFreeMemory);
    HUSH_LOAD_DEVICE(vkMapMemory);
    HUSH_LOAD_DEVICE(vkUnmapMemory);
    HUSH_LOAD_DEVICE(vkCreateCommandPool);
    HUSH_LOAD_DEVICE(vkDestroyCommandPool);
    HUSH_LOAD_DEVICE(vkAllocateCommandBuffers);
    HUSH_LOAD_DEVICE(vkBeginCommandBuffer);
    HUSH_LOAD_DEVICE(vkEndCommandBuffer);
    HUSH_LOAD_DEVICE(vkQueueSubmit);
    HUSH_LOAD_DEVICE(vkCreateFence);
    HUSH_LOAD_DEVICE(vkDestroyFence);
    HUSH_LOAD_DEVICE(vkWaitForFences);
    HUSH_LOAD_DEVICE(vkCmdPipelineBarrier);
    HUSH_LOAD_DEVICE(vkCmdCopyBufferToImage);
#undef HUSH_LOAD_DEVICE
    vkGetDeviceQueue(device, family, 0, &queue);
    REQUIRE(queue != VK_NULL_HANDLE);
}

uint32_t RawVulkan::memoryType(uint32_t allowed, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) const {
    for (VkMemoryPropertyFlags want : {required | preferred, required})
        for (uint32_t i = 0; i < memoryProps.memoryTypeCount; ++i)
            if ((allowed & (1u << i)) && (memoryProps.memoryTypes[i].propertyFlags & want) == want) return i;
    FAIL("no suitable memory type");
    return 0;
}

void RawVulkan::createBuffer(VkDeviceSize size) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    REQUIRE(vkCreateBuffer(device, &info, nullptr, &buffer) == VK_SUCCESS);
    VkMemoryRequirements req{};
    vkGetBufferMemoryRequirements(device, buffer, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = memoryType(req.memoryTypeBits,
                                       VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, 0);
    REQUIRE(vkAllocateMemory(device, &alloc, nullptr, &bufferMemory) == VK_SUCCESS);
    REQUIRE(vkBindBufferMemory(device, buffer, bufferMemory, 0) == VK_SUCCESS);
    REQUIRE(vkMapMemory(device, bufferMemory, 0, VK_WHOLE_SIZE, 0, &mapped) == VK_SUCCESS);
}

void RawVulkan::createImage(uint32_t width, uint32_t height) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    info.extent = {width, height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    REQUIRE(vkCreateImage(device, &info, nullptr, &image) == VK_SUCCESS);
    VkMemoryRequirements req{};
    vkGetImageMemoryRequirements(device, image, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = memoryType(req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    REQUIRE(vkAllocateMemory(device, &alloc, nullptr, &imageMemory) == VK_SUCCESS);
    REQUIRE(vkBindImageMemory(device, image, imageMemory, 0) == VK_SUCCESS);
}

VkCommandBuffer RawVulkan::beginCommands() {
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.queueFamilyIndex = family;
    REQUIRE(vkCreateCommandPool(device, &poolInfo, nullptr, &pool) == VK_SUCCESS);
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    REQUIRE(vkAllocateCommandBuffers(device, &alloc, &cmd) == VK_SUCCESS);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    REQUIRE(vkBeginCommandBuffer(cmd, &begin) == VK_SUCCESS);
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    REQUIRE(vkCreateFence(device, &fenceInfo, nullptr, &fence) == VK_SUCCESS);
    return cmd;
}

void RawVulkan::submitAndWait(VkCommandBuffer cmd) {
    REQUIRE(vkEndCommandBuffer(cmd) == VK_SUCCESS);
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    REQUIRE(vkQueueSubmit(queue, 1, &submit, fence) == VK_SUCCESS);
    REQUIRE(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX) == VK_SUCCESS);
}

std::vector<uint32_t> RawVulkan::mappedValues(size_t count) const {
    std::vector<uint32_t> out(count);
    std::memcpy(out.data(), mapped, count * sizeof(uint32_t));
    return out;
}

} // namespace hush::test
