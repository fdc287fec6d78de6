#include "vk_convert.hpp"

namespace hush::rhi::detail {

VkFormat toVk(Format format) {
    switch (format) {
    case Format::R8Unorm: return VK_FORMAT_R8_UNORM;
    case Format::R16Float: return VK_FORMAT_R16_SFLOAT;
    case Format::R32Float: return VK_FORMAT_R32_SFLOAT;
    case Format::RG16Float: return VK_FORMAT_R16G16_SFLOAT;
    case Format::RG32Float: return VK_FORMAT_R32G32_SFLOAT;
    case Format::RGBA8Unorm: return VK_FORMAT_R8G8B8A8_UNORM;
    case Format::RGBA16Float: return VK_FORMAT_R16G16B16A16_SFLOAT;
    case Format::RGBA32Float: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case Format::R32Uint: return VK_FORMAT_R32_UINT;
    case Format::Undefined: break;
    }
    return VK_FORMAT_UNDEFINED;
}

VkImageUsageFlags toVkImageUsage(TextureUsage usage) {
    VkImageUsageFlags flags = 0;
    if (hasAny(usage, TextureUsage::CopySrc)) flags |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    if (hasAny(usage, TextureUsage::CopyDst)) flags |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (hasAny(usage, TextureUsage::TextureBinding)) flags |= VK_IMAGE_USAGE_SAMPLED_BIT;
    if (hasAny(usage, TextureUsage::StorageBinding)) flags |= VK_IMAGE_USAGE_STORAGE_BIT;
    return flags;
}

VkBufferUsageFlags toVkBufferUsage(BufferUsage usage) {
    VkBufferUsageFlags flags = 0;
    if (hasAny(usage, BufferUsage::CopySrc)) flags |= VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    if (hasAny(usage, BufferUsage::CopyDst)) flags |= VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    if (hasAny(usage, BufferUsage::Uniform)) flags |= VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
    if (hasAny(usage, BufferUsage::Storage)) flags |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    if (hasAny(usage, BufferUsage::Indirect)) flags |= VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
    return flags;
}

VkFormatFeatureFlags requiredFormatFeatures(TextureUsage usage) {
    VkFormatFeatureFlags flags = 0;
    if (hasAny(usage, TextureUsage::CopySrc)) flags |= VK_FORMAT_FEATURE_TRANSFER_SRC_BIT;
    if (hasAny(usage, TextureUsage::CopyDst)) flags |= VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    if (hasAny(usage, TextureUsage::TextureBinding)) flags |= VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
    if (hasAny(usage, TextureUsage::StorageBinding)) flags |= VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT;
    return flags;
}

VkDescriptorType toVkDescriptorType(BindingKind kind) {
    switch (kind) {
    case BindingKind::UniformBuffer: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case BindingKind::StorageBuffer:
    case BindingKind::ReadOnlyStorageBuffer: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    case BindingKind::SampledTexture: return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    case BindingKind::CombinedTextureSampler: return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    case BindingKind::StorageTexture: return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    case BindingKind::Sampler: return VK_DESCRIPTOR_TYPE_SAMPLER;
    }
    return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

VkState toVk(ResourceState state) {
    constexpr auto compute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    switch (state) {
    case ResourceState::Undefined:
        return {VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED};
    case ResourceState::CopySrc:
        return {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
    case ResourceState::CopyDst:
        return {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
    case ResourceState::SampledRead:
        return {compute, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    case ResourceState::StorageRead:
        return {compute, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_IMAGE_LAYOUT_GENERAL};
    case ResourceState::StorageWrite:
        return {compute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_IMAGE_LAYOUT_GENERAL};
    case ResourceState::StorageReadWrite:
        return {compute, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                VK_IMAGE_LAYOUT_GENERAL};
    case ResourceState::UniformRead:
        return {compute, VK_ACCESS_2_UNIFORM_READ_BIT, VK_IMAGE_LAYOUT_GENERAL};
    case ResourceState::IndirectRead:
        return {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | compute,
                VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_IMAGE_LAYOUT_GENERAL};
    case ResourceState::HostRead:
        return {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT, VK_IMAGE_LAYOUT_GENERAL};
    case ResourceState::HostWrite:
        return {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_WRITE_BIT, VK_IMAGE_LAYOUT_GENERAL};
    case ResourceState::General:
        return {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
                VK_IMAGE_LAYOUT_GENERAL};
    }
    return {};
}

bool isExtendedStorageFormat(Format format) {
    switch (format) {
    case Format::RGBA8Unorm:
    case Format::RGBA16Float:
    case Format::RGBA32Float:
    case Format::R32Float:
    case Format::R32Uint: return false;
    default: return true;
    }
}

} // namespace hush::rhi::detail
