// Adapter: what a physical device is and can do, read once at instance creation.
#include <algorithm>
#include <cstring>

#include "objects.hpp"
#include "vk_check.hpp"
#include "vk_convert.hpp"

namespace hush::rhi {
namespace detail {

namespace {

AdapterType toAdapterType(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return AdapterType::DiscreteGpu;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return AdapterType::IntegratedGpu;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return AdapterType::VirtualGpu;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return AdapterType::Cpu;
    default: return AdapterType::Other;
    }
}

} // namespace

AdapterRecord describeAdapter(VkPhysicalDevice physical) {
    AdapterRecord record;
    record.physicalDevice = physical;

    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    subgroup.pNext = &driver;
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props.pNext = &subgroup;
    vkGetPhysicalDeviceProperties2(physical, &props);
    const auto& p = props.properties;

    auto& info = record.info;
    info.name = p.deviceName;
    info.driverName = driver.driverName;
    info.driverInfo = driver.driverInfo;
    info.type = toAdapterType(p.deviceType);
    info.vendorId = p.vendorID;
    info.deviceId = p.deviceID;
    info.apiVersion = p.apiVersion;

    auto& l = info.limits;
    l.maxTextureDimension2D = p.limits.maxImageDimension2D;
    for (int i = 0; i < 3; ++i) {
        l.maxComputeWorkgroupSize[i] = p.limits.maxComputeWorkGroupSize[i];
        l.maxComputeWorkgroupCount[i] = p.limits.maxComputeWorkGroupCount[i];
    }
    l.maxComputeInvocationsPerWorkgroup = p.limits.maxComputeWorkGroupInvocations;
    l.maxComputeSharedMemoryBytes = p.limits.maxComputeSharedMemorySize;
    l.maxPushConstantBytes = p.limits.maxPushConstantsSize;
    l.maxStorageBufferBindingBytes = p.limits.maxStorageBufferRange;
    l.maxUniformBufferBindingBytes = p.limits.maxUniformBufferRange;
    l.maxBoundDescriptorSets = p.limits.maxBoundDescriptorSets;
    l.subgroupSize = subgroup.subgroupSize;
    l.timestampPeriodNs = p.limits.timestampPeriod;

    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &familyCount, families.data());
    // Prefer a queue that does graphics and compute: it is the one engines share and
    // the one with timestamps everywhere.
    for (uint32_t pass = 0; pass < 2 && record.computeQueueFamily == ~0u; ++pass) {
        for (uint32_t i = 0; i < familyCount; ++i) {
            const auto flags = families[i].queueFlags;
            const bool wanted = pass == 0 ? (flags & VK_QUEUE_GRAPHICS_BIT) && (flags & VK_QUEUE_COMPUTE_BIT)
                                          : (flags & VK_QUEUE_COMPUTE_BIT) != 0;
            if (wanted) {
                record.computeQueueFamily = i;
                l.timestampsSupported = families[i].timestampValidBits > 0 && p.limits.timestampPeriod > 0;
                break;
            }
        }
    }

    vkGetPhysicalDeviceMemoryProperties(physical, &record.memory);
    for (uint32_t i = 0; i < record.memory.memoryHeapCount; ++i)
        if (record.memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            l.deviceLocalBytes = std::max<uint64_t>(l.deviceLocalBytes, record.memory.memoryHeaps[i].size);
    return record;
}

std::vector<AdapterRecord> enumerateAdapterRecords(VkInstance instance) {
    uint32_t count = 0;
    checkVk(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> physical(count);
    checkVk(vkEnumeratePhysicalDevices(instance, &count, physical.data()), "vkEnumeratePhysicalDevices");
    std::vector<AdapterRecord> out;
    for (auto device : physical) out.push_back(describeAdapter(device));
    return out;
}

bool formatSupports(VkPhysicalDevice physical, bool extendedStorageFormats, Format format, TextureUsage usage) {
    if (format == Format::Undefined) return false;
    if (hasAny(usage, TextureUsage::StorageBinding) && isExtendedStorageFormat(format) && !extendedStorageFormats)
        return false;
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(physical, toVk(format), &props);
    const auto needed = requiredFormatFeatures(usage);
    return (props.optimalTilingFeatures & needed) == needed;
}

bool hasExtendedStorageFormats(VkPhysicalDevice physical) {
    VkPhysicalDeviceFeatures features{};
    vkGetPhysicalDeviceFeatures(physical, &features);
    return features.shaderStorageImageExtendedFormats == VK_TRUE;
}

std::shared_ptr<DeviceImpl> createDeviceImpl(const std::shared_ptr<InstanceImpl>& instance,
                                             const AdapterRecord& record, const DeviceDesc& desc);

} // namespace detail

using namespace detail;

std::vector<std::pair<std::string, std::string>> AdapterInfo::reportFields() const {
    return {{"name", name},
            {"type", std::string(toString(type))},
            {"driver", driverName},
            {"driver_info", driverInfo},
            {"api_version", apiVersionString()}};
}

std::string AdapterInfo::apiVersionString() const {
    return std::to_string(VK_API_VERSION_MAJOR(apiVersion)) + "." + std::to_string(VK_API_VERSION_MINOR(apiVersion)) +
           "." + std::to_string(VK_API_VERSION_PATCH(apiVersion));
}

Adapter::Adapter(std::shared_ptr<InstanceImpl> instance, uint32_t index) : Handle(std::move(instance)), index_(index) {}

const AdapterInfo& Adapter::info() const { return checked(impl_, "Adapter")->adapters.at(index_).info; }

bool Adapter::supports(Format format, TextureUsage usage) const {
    const auto& record = checked(impl_, "Adapter")->adapters.at(index_);
    return formatSupports(record.physicalDevice, hasExtendedStorageFormats(record.physicalDevice), format, usage);
}

Device Adapter::createDevice(const DeviceDesc& desc) const {
    return Device(createDeviceImpl(impl_, checked(impl_, "Adapter")->adapters.at(index_), desc));
}

} // namespace hush::rhi
