#pragma once
// Instance and Adapter: the entry points. An Instance opens the Vulkan loader
// (through volk, so nothing links libvulkan at build time) and lists adapters.
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <hush/rhi/format.hpp>
#include <hush/rhi/handle.hpp>

namespace hush::rhi {

class Device;
struct DeviceDesc;

enum class AdapterType : uint8_t { DiscreteGpu, IntegratedGpu, VirtualGpu, Cpu, Other };
std::string_view toString(AdapterType type);

struct AdapterLimits {
    uint32_t maxTextureDimension2D = 0;
    uint32_t maxComputeWorkgroupSize[3] = {0, 0, 0};
    uint32_t maxComputeInvocationsPerWorkgroup = 0;
    uint32_t maxComputeWorkgroupCount[3] = {0, 0, 0};
    uint32_t maxComputeSharedMemoryBytes = 0;
    uint32_t maxPushConstantBytes = 0;
    uint32_t maxStorageBufferBindingBytes = 0;
    uint32_t maxUniformBufferBindingBytes = 0;
    uint32_t maxBoundDescriptorSets = 0;
    uint32_t subgroupSize = 0;
    double timestampPeriodNs = 0.0;   // nanoseconds per timestamp tick
    bool timestampsSupported = false; // compute queue has valid timestamp bits
    uint64_t deviceLocalBytes = 0;    // largest device-local heap
};

struct AdapterInfo {
    std::string name;
    std::string driverName;
    std::string driverInfo;
    AdapterType type = AdapterType::Other;
    uint32_t vendorId = 0;
    uint32_t deviceId = 0;
    uint32_t apiVersion = 0;          // VK_MAKE_API_VERSION encoded
    std::string apiVersionString() const;
    // name, type, driver, driver_info, api_version: what a results file records.
    std::vector<std::pair<std::string, std::string>> reportFields() const;
    AdapterLimits limits;
};

class Adapter : public Handle<detail::InstanceImpl> {
public:
    Adapter() = default;
    Adapter(std::shared_ptr<detail::InstanceImpl> instance, uint32_t index);

    const AdapterInfo& info() const;
    // Whether a texture of this format may be created with these usages.
    bool supports(Format format, TextureUsage usage) const;
    Device createDevice(const DeviceDesc& desc) const;
    uint32_t index() const { return index_; }

private:
    uint32_t index_ = 0;
};

struct InstanceDesc {
    std::string applicationName = "hush";
    // Vulkan validation layer with synchronization validation. Default: on when the
    // environment has HUSH_VALIDATION=1.
    bool validation = false;
    bool validationFromEnvironment = true;
    // The loader library to open; empty means HUSH_VULKAN_LOADER or libvulkan.so.1.
    std::string loaderLibrary;
    // Called for every validation message (after it is recorded). Default: print to
    // stderr unless the caller reads messages itself.
    std::function<void(const std::string&)> onValidationMessage;
};

struct AdapterRequest {
    // Substring of the adapter name; empty means HUSH_ADAPTER, and if that is unset
    // the first discrete GPU, else integrated, else any, else the CPU (lavapipe).
    std::string nameContains;
    bool nameFromEnvironment = true;
};

class Instance : public Handle<detail::InstanceImpl> {
public:
    using Handle::Handle;
    static Instance create(const InstanceDesc& desc = {});

    std::vector<Adapter> enumerateAdapters() const;
    Adapter requestAdapter(const AdapterRequest& request = {}) const;

    bool validationEnabled() const;
    // Every validation message since creation (or the last clear), in order.
    std::vector<std::string> validationMessages() const;
    size_t validationMessageCount() const;
    void clearValidationMessages() const;
};

} // namespace hush::rhi
