/* hush_vulkan.h: the C API with an engine's own Vulkan objects (NRD-style): a context
 * on the engine's VkDevice and queue, and denoiser inputs copied from the engine's
 * VkImages on hush's side of the queue. docs/c-api.md lists the device requirements. */
#ifndef HUSH_HUSH_VULKAN_H
#define HUSH_HUSH_VULKAN_H

#ifndef VK_NO_PROTOTYPES
#define VK_NO_PROTOTYPES
#endif
#include <vulkan/vulkan_core.h>

#include <hush/hush.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The engine's device: Vulkan 1.3 (or 1.2 with VK_KHR_synchronization2), the
 * timelineSemaphore and synchronization2 features enabled, a compute-capable queue.
 * hush uses and never destroys them; the engine destroys them after the context. */
typedef struct HushVulkanDevice {
    VkInstance instance;
    VkPhysicalDevice physicalDevice;
    VkDevice device;
    VkQueue queue;
    uint32_t queueFamilyIndex;
    PFN_vkGetInstanceProcAddr getInstanceProcAddr; /* NULL: the loader hush opens itself */
    int shaderStorageImageExtendedFormats;         /* non-zero if the engine enabled that feature */
} HushVulkanDevice;

HUSH_API HushStatus hushCreateContextFromVulkan(const HushVulkanDevice* device, HushContext* context);

/* One of the engine's images as a denoiser input. Its format must be the input's
 * (hushVulkanInputFormat), its usage must include TRANSFER_SRC, and it must be in
 * `layout` (SHADER_READ_ONLY_OPTIMAL, GENERAL or TRANSFER_SRC_OPTIMAL), where hush
 * leaves it. hush copies it on the context's queue and waits: the engine must have
 * finished writing it (a fence or vkQueueWaitIdle) before the call. */
typedef struct HushVulkanImage {
    VkImage image;
    VkFormat format;
    uint32_t width, height;
    VkImageLayout layout;
} HushVulkanImage;

HUSH_API HushStatus hushSetInputVulkanImage(HushDenoiser denoiser, const char* name, const HushVulkanImage* image);
/* The VkFormat hush holds an input in (VK_FORMAT_UNDEFINED and an error for an unknown name). */
HUSH_API VkFormat hushVulkanInputFormat(const char* name);

#ifdef __cplusplus
}
#endif

#endif /* HUSH_HUSH_VULKAN_H */
