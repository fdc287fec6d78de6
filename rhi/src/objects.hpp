#pragma once
// The implementation objects behind the public handles. Each holds a shared_ptr to
// its DeviceImpl, so a device outlives everything made from it.
#include <array>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <volk.h>

#include <hush/rhi/device.hpp>
#include <hush/rhi/live_objects.hpp>
#include <hush/core/error.hpp>

namespace hush::rhi::detail {

std::atomic<int64_t>& liveCounter(ObjectKind kind);

// A member that counts its object among the live ones of `Kind` (liveObjects()).
template <ObjectKind Kind>
struct LiveCount {
    LiveCount() { liveCounter(Kind).fetch_add(1, std::memory_order_relaxed); }
    LiveCount(const LiveCount&) : LiveCount() {}
    LiveCount& operator=(const LiveCount&) { return *this; }
    ~LiveCount() { liveCounter(Kind).fetch_sub(1, std::memory_order_relaxed); }
};

using KeepAlive = std::vector<std::shared_ptr<const void>>;

struct AdapterRecord {
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    AdapterInfo info;
    uint32_t computeQueueFamily = ~0u;
    VkPhysicalDeviceMemoryProperties memory{};
};

struct InstanceImpl {
    LiveCount<ObjectKind::Instance> live;
    void* loader = nullptr;               // dlopen handle; null for an imported device's loader
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    // This instance's own entry point: volk's global one is reloaded by every
    // Instance::create, and an instance without debug utils would null it.
    PFN_vkDestroyDebugUtilsMessengerEXT destroyMessenger = nullptr;
    bool validation = false;
    std::vector<AdapterRecord> adapters;

    std::mutex messageMutex;
    std::vector<std::string> messages;
    std::function<void(const std::string&)> onMessage;

    ~InstanceImpl();
};

// What one submission keeps alive. The common case, one command buffer, needs no
// heap allocation, so a render graph's frames submit without allocating.
struct InFlight {
    SubmissionId id = 0;
    std::shared_ptr<const void> first;
    KeepAlive more;
};

struct DeviceImpl {
    LiveCount<ObjectKind::Device> live;
    std::shared_ptr<InstanceImpl> instance;   // null for an imported device
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    bool ownsDevice = true;
    VolkDeviceTable vk{};
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    AdapterInfo info;
    VkPhysicalDeviceMemoryProperties memory{};
    VkPhysicalDeviceLimits limits{};
    uint64_t maxBufferSize = 0;
    bool extendedStorageFormats = false;   // shaderStorageImageExtendedFormats is enabled
    std::string label;

    VkSemaphore timeline = VK_NULL_HANDLE;
    std::mutex queueMutex;
    SubmissionId lastSubmitted = 0;
    std::vector<InFlight> inFlight;   // oldest first; capacity is kept between frames
    std::atomic<uint64_t> allocatedBytes{0};
    // Set once a submission or wait reported VK_ERROR_DEVICE_LOST: a lost device
    // stays lost, so later calls fail the same way without asking the driver.
    std::atomic<bool> lost{false};

    ~DeviceImpl();

    // Drops what completed submissions kept alive. Call with queueMutex held.
    void retireCompleted();
    uint64_t completedValue() const;

    // Device memory for `requirements`, preferring `preferred` properties among
    // types with `required` ones. Throws OutOfMemory naming `what`.
    VkDeviceMemory allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags required,
                            VkMemoryPropertyFlags preferred, const std::string& what,
                            VkMemoryPropertyFlags* chosenFlags = nullptr, uint32_t* chosenType = nullptr);
    void free(VkDeviceMemory memory, uint64_t bytes);
};

struct BufferImpl {
    LiveCount<ObjectKind::Buffer> live;
    std::shared_ptr<DeviceImpl> device;
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    uint64_t allocationBytes = 0;
    BufferDesc desc;
    void* mapped = nullptr;
    bool coherent = true;
    bool owned = true;
    ~BufferImpl();
};

struct MemoryBlockImpl {
    LiveCount<ObjectKind::MemoryBlock> live;
    std::shared_ptr<DeviceImpl> device;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    uint64_t size = 0;
    uint32_t memoryTypeBits = 0;
    std::string label;
    ~MemoryBlockImpl();
};

struct TextureImpl {
    LiveCount<ObjectKind::Texture> live;
    std::shared_ptr<DeviceImpl> device;
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;   // null when placed in a MemoryBlock
    std::shared_ptr<MemoryBlockImpl> block;
    uint64_t blockOffset = 0;
    uint64_t allocationBytes = 0;
    VkImageView defaultView = VK_NULL_HANDLE;
    TextureDesc desc;
    bool owned = true;
    ~TextureImpl();
};

struct TextureViewImpl {
    LiveCount<ObjectKind::TextureView> live;
    std::shared_ptr<TextureImpl> texture;
    VkImageView view = VK_NULL_HANDLE;
    uint32_t baseMip = 0;
    uint32_t mipCount = 1;
    bool ownsView = true;
    ~TextureViewImpl();
};

struct SamplerImpl {
    LiveCount<ObjectKind::Sampler> live;
    std::shared_ptr<DeviceImpl> device;
    VkSampler sampler = VK_NULL_HANDLE;
    SamplerDesc desc;
    ~SamplerImpl();
};

struct ShaderModuleImpl {
    LiveCount<ObjectKind::ShaderModule> live;
    std::shared_ptr<DeviceImpl> device;
    VkShaderModule module = VK_NULL_HANDLE;
    std::string label;
    ShaderReflection reflection;
    ~ShaderModuleImpl();
};

struct BindGroupLayoutImpl {
    LiveCount<ObjectKind::BindGroupLayout> live;
    std::shared_ptr<DeviceImpl> device;
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    std::string label;
    std::string origin;   // "pipeline 'svgf.atrous' set 0" or "bind group layout 'x'"
    std::vector<BindGroupLayoutEntry> entries;
    ~BindGroupLayoutImpl();
};

struct BindGroupImpl {
    LiveCount<ObjectKind::BindGroup> live;
    std::shared_ptr<DeviceImpl> device;
    std::shared_ptr<BindGroupLayoutImpl> layout;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
    std::string label;
    KeepAlive resources;
    ~BindGroupImpl();
};

struct ComputePipelineImpl {
    LiveCount<ObjectKind::ComputePipeline> live;
    std::shared_ptr<DeviceImpl> device;
    std::shared_ptr<ShaderModuleImpl> module;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    std::vector<std::shared_ptr<BindGroupLayoutImpl>> setLayouts;
    std::vector<bool> setUsed;   // sets the shader declares (must be bound to dispatch)
    uint32_t pushConstantBytes = 0;
    uint32_t shaderPushConstantBytes = 0;
    std::array<uint32_t, 3> workgroupSize = {1, 1, 1};
    std::vector<ConstantEntry> constants;
    std::string label;
    ~ComputePipelineImpl();
};

struct QuerySetImpl {
    LiveCount<ObjectKind::QuerySet> live;
    std::shared_ptr<DeviceImpl> device;
    VkQueryPool pool = VK_NULL_HANDLE;
    uint32_t count = 0;
    std::string label;
    ~QuerySetImpl();
};

struct CommandBufferImpl {
    LiveCount<ObjectKind::CommandBuffer> live;
    std::shared_ptr<DeviceImpl> device;
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
    bool external = false;
    bool submitted = false;
    SubmissionId submission = 0;
    std::string label;
    KeepAlive keepAlive;
    ~CommandBufferImpl();
};

struct CommandEncoderImpl {
    LiveCount<ObjectKind::CommandEncoder> live;
    std::shared_ptr<DeviceImpl> device;
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
    bool external = false;
    bool finished = false;
    bool reusable = false;
    bool trackLifetimes = true;
    std::string label;
    KeepAlive keepAlive;
    std::shared_ptr<CommandBufferImpl> reusableBuffer;   // reusable encoders hand out this one

    // Scratch space for barriers, kept between calls so that recording does not allocate.
    std::vector<VkImageMemoryBarrier2> imageBarriers;
    std::vector<VkBufferMemoryBarrier2> bufferBarriers;
    std::vector<VkMemoryBarrier2> memoryBarriers;

    // The open compute pass, if any.
    bool inPass = false;
    std::string passLabel;
    std::shared_ptr<QuerySetImpl> passQueries;
    uint32_t passEndQuery = 0;
    std::shared_ptr<ComputePipelineImpl> pipeline;
    std::vector<std::shared_ptr<BindGroupImpl>> boundGroups;
    uint32_t pushConstantBytesSet = 0;

    ~CommandEncoderImpl();
    template <class T> void retain(const std::shared_ptr<T>& object) {
        if (trackLifetimes) keepAlive.push_back(object);
    }
    void requireRecording(const char* call) const;
    void requireOutsidePass(const char* call) const;
};

// Device that owns `impl`, with a check that the object is alive.
template <class T>
T* checked(const std::shared_ptr<T>& impl, const char* what) {
    if (!impl) throw Error(ErrorKind::InvalidArgument, std::string("use of an empty ") + what + " handle");
    return impl.get();
}

} // namespace hush::rhi::detail
