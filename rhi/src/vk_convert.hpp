#pragma once
// Mappings from hush's enums to Vulkan's: formats, usages, resource states.
#include <volk.h>

#include <hush/rhi/bind_group.hpp>
#include <hush/rhi/format.hpp>
#include <hush/rhi/resource_state.hpp>

namespace hush::rhi::detail {

VkFormat toVk(Format format);
VkImageUsageFlags toVkImageUsage(TextureUsage usage);
VkBufferUsageFlags toVkBufferUsage(BufferUsage usage);
VkFormatFeatureFlags requiredFormatFeatures(TextureUsage usage);
VkDescriptorType toVkDescriptorType(BindingKind kind);

struct VkState {
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
};
VkState toVk(ResourceState state);

// Storage formats beyond the core set need shaderStorageImageExtendedFormats.
bool isExtendedStorageFormat(Format format);

} // namespace hush::rhi::detail
