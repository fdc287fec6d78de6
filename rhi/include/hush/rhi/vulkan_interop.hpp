#pragma once
// Interop with an engine's own Vulkan objects, so hush can run inside its frame.
// This is the only public header that names Vulkan types.
//
// Requirements on an imported device: Vulkan 1.3 (or 1.2 with the
// synchronization2 extension enabled), with the timelineSemaphore and
// synchronization2 features enabled, and a queue that supports compute.
#ifndef VK_NO_PROTOTYPES
#define VK_NO_PROTOTYPES
#endif
#include <vulkan/vulkan_core.h>

#include <hush/rhi/device.hpp>

namespace hush::rhi {

struct VulkanDeviceImport {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamilyIndex = 0;
    // The engine's loader entry point; null means the loader hush opens itself.
    PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
    std::string label = "imported";
    // Whether the engine enabled shaderStorageImageExtendedFormats: without it, hush
    // refuses storage use of r8unorm, r16float, rg16float and rg32float textures.
    bool shaderStorageImageExtendedFormats = false;
};

// A Device that uses, and never destroys, the engine's VkDevice and VkQueue.
Device importVulkanDevice(const VulkanDeviceImport& desc);

// Textures and buffers that wrap (and never destroy) the engine's objects. The
// descriptor must describe them truthfully: format, size and usage are used for
// validation, views and barriers.
Texture wrapVulkanImage(const Device& device, VkImage image, const TextureDesc& desc);
Buffer wrapVulkanBuffer(const Device& device, VkBuffer buffer, const BufferDesc& desc);

// An encoder that records into the engine's command buffer (already begun). The
// engine submits it; finish() returns an empty CommandBuffer, and keeping the
// resources alive until the GPU is done is then the engine's job.
CommandEncoder encodeIntoVulkanCommandBuffer(const Device& device, VkCommandBuffer commandBuffer);

VkDevice vulkanDevice(const Device& device);
VkImage vulkanImage(const Texture& texture);
VkBuffer vulkanBuffer(const Buffer& buffer);
VkFormat vulkanFormat(Format format);

} // namespace hush::rhi
