// Device: the VkDevice with one compute queue, a timeline semaphore that numbers
// submissions, and device-memory allocation with errors that say what was asked.
#include <algorithm>

#include "fault_injection_detail.hpp"
#include "objects.hpp"
#include "vk_check.hpp"

namespace hush::rhi {
namespace detail {

DeviceImpl::~DeviceImpl() {
    if (device == VK_NULL_HANDLE) return;
    vk.vkDeviceWaitIdle(device);
    {
        std::lock_guard lock(queueMutex);
        inFlight.clear();
    }
    if (timeline != VK_NULL_HANDLE) vk.vkDestroySemaphore(device, timeline, nullptr);
    if (ownsDevice) vk.vkDestroyDevice(device, nullptr);
}

uint64_t DeviceImpl::completedValue() const {
    uint64_t value = 0;
    checkVk(vk.vkGetSemaphoreCounterValue(device, timeline, &value), "vkGetSemaphoreCounterValue");
    return value;
}

void DeviceImpl::retireCompleted() {
    if (inFlight.empty()) return;
    const uint64_t done = completedValue();
    size_t retired = 0;
    while (retired < inFlight.size() && inFlight[retired].id <= done) ++retired;
    if (retired) inFlight.erase(inFlight.begin(), inFlight.begin() + ptrdiff_t(retired));
}

VkDeviceMemory DeviceImpl::allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags required,
                                    VkMemoryPropertyFlags preferred, const std::string& what,
                                    VkMemoryPropertyFlags* chosenFlags, uint32_t* chosenType) {
    uint32_t chosen = ~0u;
    for (int pass = 0; pass < 2 && chosen == ~0u; ++pass) {
        const VkMemoryPropertyFlags want = pass == 0 ? (required | preferred) : required;
        for (uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
            if (!(requirements.memoryTypeBits & (1u << i))) continue;
            if ((memory.memoryTypes[i].propertyFlags & want) == want) {
                chosen = i;
                break;
            }
        }
    }
    if (chosen == ~0u)
        fail(ErrorKind::Unsupported, what + ": adapter '" + info.name + "' has no memory type with the needed properties");
    const auto heapSize = memory.memoryHeaps[memory.memoryTypes[chosen].heapIndex].size;
    if (requirements.size > heapSize)
        fail(ErrorKind::OutOfMemory, what + " needs " + std::to_string(requirements.size) + " bytes, more than the " +
                                         std::to_string(heapSize) + " bytes of memory heap " +
                                         std::to_string(memory.memoryTypes[chosen].heapIndex) + " on '" + info.name +
                                         "'. Use a smaller size.");
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = requirements.size;
    alloc.memoryTypeIndex = chosen;
    VkDeviceMemory out = VK_NULL_HANDLE;
    const VkResult result = takeInjectedFault(InjectedFault::OutOfDeviceMemory)
                                ? VK_ERROR_OUT_OF_DEVICE_MEMORY
                                : vk.vkAllocateMemory(device, &alloc, nullptr, &out);
    checkVk(result, "allocating " + std::to_string(requirements.size) + " bytes for " + what);
    allocatedBytes += requirements.size;
    if (chosenFlags) *chosenFlags = memory.memoryTypes[chosen].propertyFlags;
    if (chosenType) *chosenType = chosen;
    return out;
}

void DeviceImpl::free(VkDeviceMemory mem, uint64_t bytes) {
    if (mem == VK_NULL_HANDLE) return;
    vk.vkFreeMemory(device, mem, nullptr);
    allocatedBytes -= bytes;
}

void createTimeline(DeviceImpl& impl) {
    VkSemaphoreTypeCreateInfo type{VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO};
    type.semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE;
    type.initialValue = 0;
    VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    info.pNext = &type;
    checkVk(impl.vk.vkCreateSemaphore(impl.device, &info, nullptr, &impl.timeline), "creating the queue timeline");
}

void readDeviceLimits(DeviceImpl& impl) {
    VkPhysicalDeviceMaintenance4Properties m4{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_PROPERTIES};
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props.pNext = &m4;
    vkGetPhysicalDeviceProperties2(impl.physicalDevice, &props);
    impl.limits = props.properties.limits;
    impl.maxBufferSize = m4.maxBufferSize;
    vkGetPhysicalDeviceMemoryProperties(impl.physicalDevice, &impl.memory);
}

std::shared_ptr<DeviceImpl> createDeviceImpl(const std::shared_ptr<InstanceImpl>& instance,
                                             const AdapterRecord& record, const DeviceDesc& desc) {
    const auto& info = record.info;
    if (info.apiVersion < VK_API_VERSION_1_3)
        fail(ErrorKind::Unsupported, "adapter '" + info.name + "' supports Vulkan " + info.apiVersionString() +
                                         "; hush needs 1.3 (update the driver).");
    if (record.computeQueueFamily == ~0u)
        fail(ErrorKind::Unsupported, "adapter '" + info.name + "' has no compute queue.");

    VkPhysicalDeviceVulkan13Features have13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceVulkan12Features have12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    have12.pNext = &have13;
    VkPhysicalDeviceFeatures2 have{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    have.pNext = &have12;
    vkGetPhysicalDeviceFeatures2(record.physicalDevice, &have);
    if (!have13.synchronization2 || !have12.timelineSemaphore)
        fail(ErrorKind::Unsupported, "adapter '" + info.name + "' lacks synchronization2 or timeline semaphores.");

    VkPhysicalDeviceVulkan13Features enable13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    enable13.synchronization2 = VK_TRUE;
    enable13.maintenance4 = have13.maintenance4;
    VkPhysicalDeviceVulkan12Features enable12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    enable12.pNext = &enable13;
    enable12.timelineSemaphore = VK_TRUE;
    enable12.shaderFloat16 = have12.shaderFloat16;
    enable12.storageBuffer8BitAccess = have12.storageBuffer8BitAccess;
    VkPhysicalDeviceFeatures2 enable{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    enable.pNext = &enable12;
    // Formats and access the denoisers' shaders rely on, where the adapter has them.
    enable.features.shaderStorageImageExtendedFormats = have.features.shaderStorageImageExtendedFormats;
    enable.features.shaderInt64 = have.features.shaderInt64;
    enable.features.shaderInt16 = have.features.shaderInt16;

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = record.computeQueueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    deviceInfo.pNext = &enable;
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;

    auto impl = std::make_shared<DeviceImpl>();
    impl->instance = instance;
    impl->physicalDevice = record.physicalDevice;
    impl->info = info;
    impl->queueFamily = record.computeQueueFamily;
    impl->label = desc.label;
    impl->extendedStorageFormats = have.features.shaderStorageImageExtendedFormats == VK_TRUE;
    checkVk(vkCreateDevice(record.physicalDevice, &deviceInfo, nullptr, &impl->device),
            "vkCreateDevice on '" + info.name + "'");
    volkLoadDeviceTable(&impl->vk, impl->device);
    impl->vk.vkGetDeviceQueue(impl->device, impl->queueFamily, 0, &impl->queue);
    readDeviceLimits(*impl);
    createTimeline(*impl);
    return impl;
}

} // namespace detail

using namespace detail;

const AdapterInfo& Device::adapterInfo() const { return checked(impl_, "Device")->info; }
Queue Device::queue() const {
    checked(impl_, "Device");
    return Queue(impl_);
}
uint64_t Device::allocatedBytes() const { return checked(impl_, "Device")->allocatedBytes.load(); }

void Device::waitIdle() const {
    auto* impl = checked(impl_, "Device");
    std::lock_guard lock(impl->queueMutex);
    checkVk(impl->vk.vkQueueWaitIdle(impl->queue), "vkQueueWaitIdle");
    impl->retireCompleted();
}

} // namespace hush::rhi
