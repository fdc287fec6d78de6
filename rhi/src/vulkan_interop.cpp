// Interop: a Device over an engine's VkDevice, and hush objects over its images,
// buffers and command buffers. hush never destroys what it did not create.
#include <hush/rhi/vulkan_interop.hpp>

#include "objects.hpp"
#include "vk_check.hpp"
#include "vk_convert.hpp"

namespace hush::rhi {
namespace detail {

void* openLoader(const std::string& requested);
AdapterRecord describeAdapter(VkPhysicalDevice physical);
void createTimeline(DeviceImpl& impl);
void readDeviceLimits(DeviceImpl& impl);
void validateTextureDesc(const DeviceImpl& device, const TextureDesc& desc);
VkImageView createImageView(DeviceImpl& device, VkImage image, Format format, uint32_t baseMip, uint32_t mipCount,
                            const std::string& what);
std::shared_ptr<CommandEncoderImpl> makeEncoder(const std::shared_ptr<DeviceImpl>& device, const std::string& label,
                                                VkCommandBuffer external, bool reusable, bool trackLifetimes);

} // namespace detail

using namespace detail;

Device importVulkanDevice(const VulkanDeviceImport& desc) {
    if (!desc.instance || !desc.physicalDevice || !desc.device || !desc.queue)
        fail(ErrorKind::InvalidArgument, "importVulkanDevice '" + desc.label +
                                             "': instance, physicalDevice, device and queue must all be set");
    if (desc.getInstanceProcAddr) volkInitializeCustom(desc.getInstanceProcAddr);
    else openLoader("");
    volkLoadInstanceOnly(desc.instance);

    const auto record = describeAdapter(desc.physicalDevice);
    if (record.info.apiVersion < VK_API_VERSION_1_3)
        fail(ErrorKind::Unsupported, "imported device '" + record.info.name + "' reports Vulkan " +
                                         record.info.apiVersionString() + "; hush needs 1.3");
    auto impl = std::make_shared<DeviceImpl>();
    impl->physicalDevice = desc.physicalDevice;
    impl->device = desc.device;
    impl->ownsDevice = false;
    impl->queue = desc.queue;
    impl->queueFamily = desc.queueFamilyIndex;
    impl->info = record.info;
    impl->label = desc.label;
    impl->extendedStorageFormats = desc.shaderStorageImageExtendedFormats;
    volkLoadDeviceTable(&impl->vk, desc.device);
    readDeviceLimits(*impl);
    createTimeline(*impl);
    return Device(std::move(impl));
}

Texture wrapVulkanImage(const Device& device, VkImage image, const TextureDesc& desc) {
    auto* d = checked(device.shared(), "Device");
    if (image == VK_NULL_HANDLE) fail(ErrorKind::InvalidArgument, "wrapVulkanImage '" + desc.label + "': null VkImage");
    validateTextureDesc(*d, desc);
    auto impl = std::make_shared<TextureImpl>();
    impl->device = device.shared();
    impl->image = image;
    impl->desc = desc;
    impl->owned = false;
    if (hasAny(desc.usage, TextureUsage::TextureBinding | TextureUsage::StorageBinding))
        impl->defaultView = createImageView(*d, image, desc.format, 0, desc.mipLevelCount, "texture '" + desc.label + "'");
    return Texture(std::move(impl));
}

Buffer wrapVulkanBuffer(const Device& device, VkBuffer buffer, const BufferDesc& desc) {
    checked(device.shared(), "Device");
    if (buffer == VK_NULL_HANDLE) fail(ErrorKind::InvalidArgument, "wrapVulkanBuffer '" + desc.label + "': null VkBuffer");
    if (desc.size == 0) fail(ErrorKind::InvalidArgument, "wrapVulkanBuffer '" + desc.label + "': size 0");
    if (hasAny(desc.usage, BufferUsage::MapRead | BufferUsage::MapWrite))
        fail(ErrorKind::InvalidArgument, "wrapVulkanBuffer '" + desc.label +
                                             "': a wrapped buffer cannot be mapped by hush; map it in the engine");
    auto impl = std::make_shared<BufferImpl>();
    impl->device = device.shared();
    impl->buffer = buffer;
    impl->desc = desc;
    impl->owned = false;
    return Buffer(std::move(impl));
}

CommandEncoder encodeIntoVulkanCommandBuffer(const Device& device, VkCommandBuffer commandBuffer) {
    checked(device.shared(), "Device");
    if (commandBuffer == VK_NULL_HANDLE)
        fail(ErrorKind::InvalidArgument, "encodeIntoVulkanCommandBuffer: null VkCommandBuffer");
    return CommandEncoder(makeEncoder(device.shared(), "engine command buffer", commandBuffer, false, true));
}

VkDevice vulkanDevice(const Device& device) { return checked(device.shared(), "Device")->device; }
VkImage vulkanImage(const Texture& texture) { return checked(texture.shared(), "Texture")->image; }
VkBuffer vulkanBuffer(const Buffer& buffer) { return checked(buffer.shared(), "Buffer")->buffer; }
VkFormat vulkanFormat(Format format) { return toVk(format); }

} // namespace hush::rhi
