// Texture, TextureView and Sampler: 2D, optimal tiling, device-local.
#include <algorithm>

#include "objects.hpp"
#include "vk_check.hpp"
#include "vk_convert.hpp"

namespace hush::rhi {
namespace detail {

bool formatSupports(VkPhysicalDevice physical, bool extendedStorageFormats, Format format, TextureUsage usage);

TextureImpl::~TextureImpl() {
    if (defaultView != VK_NULL_HANDLE) device->vk.vkDestroyImageView(device->device, defaultView, nullptr);
    if (!owned || image == VK_NULL_HANDLE) return;
    device->vk.vkDestroyImage(device->device, image, nullptr);
    device->free(memory, allocationBytes);
}

MemoryBlockImpl::~MemoryBlockImpl() { device->free(memory, size); }

TextureViewImpl::~TextureViewImpl() {
    if (ownsView && view != VK_NULL_HANDLE)
        texture->device->vk.vkDestroyImageView(texture->device->device, view, nullptr);
}

SamplerImpl::~SamplerImpl() {
    if (sampler != VK_NULL_HANDLE) device->vk.vkDestroySampler(device->device, sampler, nullptr);
}

VkImageView createImageView(DeviceImpl& device, VkImage image, Format format, uint32_t baseMip, uint32_t mipCount,
                            const std::string& what) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image;
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = toVk(format);
    info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, baseMip, mipCount, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    checkVk(device.vk.vkCreateImageView(device.device, &info, nullptr, &view), "vkCreateImageView for " + what);
    return view;
}

// Checks a texture descriptor against the adapter; shared by creation and wrapping.
void validateTextureDesc(const DeviceImpl& device, const TextureDesc& desc) {
    const std::string what = "texture '" + desc.label + "'";
    if (desc.format == Format::Undefined) fail(ErrorKind::InvalidArgument, what + " has format undefined");
    if (desc.size.width == 0 || desc.size.height == 0)
        fail(ErrorKind::InvalidArgument, what + " has size " + std::to_string(desc.size.width) + "x" +
                                             std::to_string(desc.size.height) + "; both must be at least 1");
    if (desc.usage == TextureUsage::None) fail(ErrorKind::InvalidArgument, what + " has no usage");
    const uint32_t maxDim = device.limits.maxImageDimension2D;
    if (desc.size.width > maxDim || desc.size.height > maxDim)
        fail(ErrorKind::Unsupported, what + " is " + std::to_string(desc.size.width) + "x" +
                                         std::to_string(desc.size.height) + ", larger than the adapter limit "
                                         "maxTextureDimension2D = " + std::to_string(maxDim) + " of '" +
                                         device.info.name + "'");
    uint32_t maxMips = 1;
    for (uint32_t s = std::max(desc.size.width, desc.size.height); s > 1; s >>= 1) ++maxMips;
    if (desc.mipLevelCount == 0 || desc.mipLevelCount > maxMips)
        fail(ErrorKind::InvalidArgument, what + " asks for " + std::to_string(desc.mipLevelCount) +
                                             " mip levels; its size allows 1 to " + std::to_string(maxMips));
    if (!formatSupports(device.physicalDevice, device.extendedStorageFormats, desc.format, desc.usage))
        fail(ErrorKind::Unsupported, what + ": adapter '" + device.info.name + "' does not support format " +
                                         std::string(toString(desc.format)) + " with usage " + toString(desc.usage));
}

} // namespace detail

using namespace detail;

namespace {

VkImageCreateInfo imageInfo(const TextureDesc& desc) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = toVk(desc.format);
    info.extent = {desc.size.width, desc.size.height, 1};
    info.mipLevels = desc.mipLevelCount;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = toVkImageUsage(desc.usage);
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    return info;
}

// Creates the image and binds it to its own allocation, or to `block` at `offset`.
Texture makeTexture(const std::shared_ptr<DeviceImpl>& devicePtr, const TextureDesc& desc,
                    const std::shared_ptr<MemoryBlockImpl>& block, uint64_t offset) {
    auto* device = devicePtr.get();
    validateTextureDesc(*device, desc);
    const std::string what = "texture '" + desc.label + "'";
    auto impl = std::make_shared<TextureImpl>();
    impl->device = devicePtr;
    impl->desc = desc;
    const auto info = imageInfo(desc);
    checkVk(device->vk.vkCreateImage(device->device, &info, nullptr, &impl->image), "vkCreateImage for " + what);

    VkMemoryRequirements req{};
    device->vk.vkGetImageMemoryRequirements(device->device, impl->image, &req);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    try {
        if (block) {
            if (offset % req.alignment || offset + req.size > block->size || !(req.memoryTypeBits & block->memoryTypeBits))
                fail(ErrorKind::InvalidArgument,
                     what + " (" + std::to_string(req.size) + " bytes, alignment " + std::to_string(req.alignment) +
                         ") does not fit at offset " + std::to_string(offset) + " of memory block '" + block->label +
                         "' (" + std::to_string(block->size) + " bytes)");
            memory = block->memory;
        } else {
            impl->memory = device->allocate(req, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, what);
            impl->allocationBytes = req.size;
            memory = impl->memory;
        }
    } catch (...) {
        device->vk.vkDestroyImage(device->device, impl->image, nullptr);
        impl->image = VK_NULL_HANDLE;
        throw;
    }
    impl->block = block;
    impl->blockOffset = offset;
    checkVk(device->vk.vkBindImageMemory(device->device, impl->image, memory, block ? offset : 0),
            "binding memory of " + what);
    if (hasAny(desc.usage, TextureUsage::TextureBinding | TextureUsage::StorageBinding))   // copy-only images have no views
        impl->defaultView = createImageView(*device, impl->image, desc.format, 0, desc.mipLevelCount, what);
    return Texture(std::move(impl));
}

} // namespace

Texture Device::createTexture(const TextureDesc& desc) const {
    checked(impl_, "Device");
    return makeTexture(impl_, desc, nullptr, 0);
}

Texture Device::createTexture(const TextureDesc& desc, const MemoryBlock& block, uint64_t offset) const {
    checked(impl_, "Device");
    auto b = checked(block.shared(), "MemoryBlock");
    if (b->device != impl_) fail(ErrorKind::InvalidArgument, "memory block '" + b->label + "' belongs to another device");
    return makeTexture(impl_, desc, block.shared(), offset);
}

MemoryRequirements Device::textureMemoryRequirements(const TextureDesc& desc) const {
    auto* device = checked(impl_, "Device");
    validateTextureDesc(*device, desc);
    const auto info = imageInfo(desc);
    VkDeviceImageMemoryRequirements query{VK_STRUCTURE_TYPE_DEVICE_IMAGE_MEMORY_REQUIREMENTS};
    query.pCreateInfo = &info;
    VkMemoryRequirements2 req{VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2};
    device->vk.vkGetDeviceImageMemoryRequirements(device->device, &query, &req);
    return {req.memoryRequirements.size, req.memoryRequirements.alignment, req.memoryRequirements.memoryTypeBits};
}

MemoryBlock Device::createMemoryBlock(const MemoryBlockDesc& desc) const {
    auto* device = checked(impl_, "Device");
    if (desc.size == 0) fail(ErrorKind::InvalidArgument, "memory block '" + desc.label + "' has size 0");
    auto impl = std::make_shared<MemoryBlockImpl>();
    impl->device = impl_;
    impl->label = desc.label;
    impl->size = desc.size;
    VkMemoryRequirements req{desc.size, 1, desc.memoryTypeBits};
    uint32_t type = 0;
    impl->memory = device->allocate(req, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "memory block '" + desc.label + "'",
                                    nullptr, &type);
    impl->memoryTypeBits = 1u << type;   // a placed texture must accept this one type
    return MemoryBlock(std::move(impl));
}

const std::string& MemoryBlock::label() const { return checked(impl_, "MemoryBlock")->label; }
uint64_t MemoryBlock::size() const { return checked(impl_, "MemoryBlock")->size; }

const std::string& Texture::label() const { return checked(impl_, "Texture")->desc.label; }
Extent2D Texture::size() const { return checked(impl_, "Texture")->desc.size; }
Format Texture::format() const { return checked(impl_, "Texture")->desc.format; }
TextureUsage Texture::usage() const { return checked(impl_, "Texture")->desc.usage; }
uint32_t Texture::mipLevelCount() const { return checked(impl_, "Texture")->desc.mipLevelCount; }

uint64_t Texture::byteSize() const {
    const auto& d = checked(impl_, "Texture")->desc;
    return uint64_t(d.size.width) * d.size.height * formatInfo(d.format).bytesPerPixel;
}

TextureView Texture::defaultView() const {
    auto* impl = checked(impl_, "Texture");
    if (impl->defaultView == VK_NULL_HANDLE)
        fail(ErrorKind::InvalidArgument, "texture '" + impl->desc.label + "' has usage " + toString(impl->desc.usage) +
                                             ": a view needs texture-binding or storage-binding");
    auto view = std::make_shared<TextureViewImpl>();
    view->texture = impl_;
    view->view = impl->defaultView;
    view->baseMip = 0;
    view->mipCount = impl->desc.mipLevelCount;
    view->ownsView = false;   // the texture owns its default view
    return TextureView(std::move(view));
}

TextureView Texture::createView(uint32_t baseMipLevel, uint32_t mipLevelCount) const {
    auto* impl = checked(impl_, "Texture");
    if (!hasAny(impl->desc.usage, TextureUsage::TextureBinding | TextureUsage::StorageBinding))
        fail(ErrorKind::InvalidArgument, "texture '" + impl->desc.label + "' has usage " + toString(impl->desc.usage) +
                                             ": a view needs texture-binding or storage-binding");
    if (mipLevelCount == 0 || baseMipLevel + mipLevelCount > impl->desc.mipLevelCount)
        fail(ErrorKind::InvalidArgument, "view of mips [" + std::to_string(baseMipLevel) + ", " +
                                             std::to_string(baseMipLevel + mipLevelCount) + ") of texture '" +
                                             impl->desc.label + "', which has " +
                                             std::to_string(impl->desc.mipLevelCount) + " mips");
    auto view = std::make_shared<TextureViewImpl>();
    view->texture = impl_;
    view->view = createImageView(*impl->device, impl->image, impl->desc.format, baseMipLevel, mipLevelCount,
                                 "texture '" + impl->desc.label + "'");
    view->baseMip = baseMipLevel;
    view->mipCount = mipLevelCount;
    return TextureView(std::move(view));
}

Texture TextureView::texture() const { return Texture(checked(impl_, "TextureView")->texture); }
Format TextureView::format() const { return checked(impl_, "TextureView")->texture->desc.format; }
uint32_t TextureView::baseMipLevel() const { return checked(impl_, "TextureView")->baseMip; }
uint32_t TextureView::mipLevelCount() const { return checked(impl_, "TextureView")->mipCount; }

Sampler Device::createSampler(const SamplerDesc& desc) const {
    auto* device = checked(impl_, "Device");
    auto filter = [](FilterMode m) { return m == FilterMode::Linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST; };
    auto address = [](AddressMode m) {
        switch (m) {
        case AddressMode::Repeat: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
        case AddressMode::MirrorRepeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
        default: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        }
    };
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = filter(desc.magFilter);
    info.minFilter = filter(desc.minFilter);
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = address(desc.addressModeU);
    info.addressModeV = address(desc.addressModeV);
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.maxLod = VK_LOD_CLAMP_NONE;
    auto impl = std::make_shared<SamplerImpl>();
    impl->device = impl_;
    impl->desc = desc;
    checkVk(device->vk.vkCreateSampler(device->device, &info, nullptr, &impl->sampler),
            "vkCreateSampler for sampler '" + desc.label + "'");
    return Sampler(std::move(impl));
}

const std::string& Sampler::label() const { return checked(impl_, "Sampler")->desc.label; }

} // namespace hush::rhi
