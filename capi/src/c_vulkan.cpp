// The C API over an engine's own Vulkan objects (hush_vulkan.h): a context on its
// VkDevice, and inputs copied from its VkImages.
#include <string>

#include <hush/hush_vulkan.h>
#include <hush/rhi/vulkan_interop.hpp>

#include "c_api_guard.hpp"
#include "c_objects.hpp"

using namespace hush;
using capi::badArgument;
using capi::guarded;
using capi::required;

namespace {

rhi::ResourceState stateOf(VkImageLayout layout) {
    switch (layout) {
    case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL: return rhi::ResourceState::SampledRead;
    case VK_IMAGE_LAYOUT_GENERAL: return rhi::ResourceState::General;
    case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL: return rhi::ResourceState::CopySrc;
    default: break;
    }
    badArgument("image->layout", "is VkImageLayout " + std::to_string(int(layout)) +
                                     "; use SHADER_READ_ONLY_OPTIMAL, GENERAL or TRANSFER_SRC_OPTIMAL");
}

// Copies the engine's image into the input texture on hush's queue and waits, leaving
// the engine's image in the layout it came in.
void copyIntoInput(HushDenoiser_T& d, passes::InputChannel channel, const rhi::Texture& source, rhi::ResourceState state) {
    const rhi::Device& device = d.context->device;
    const rhi::Texture& input = d.runner->inputs().texture(channel);
    const auto inputBefore = d.set[size_t(channel)] ? rhi::ResourceState::SampledRead : rhi::ResourceState::Undefined;
    rhi::CommandEncoder encoder = device.createCommandEncoder({.label = "hush-c.copy-input"});
    encoder.barrier({{source, state, rhi::ResourceState::CopySrc}, {input, inputBefore, rhi::ResourceState::CopyDst}});
    encoder.copyTextureToTexture({.texture = source}, {.texture = input});
    encoder.barrier({{source, rhi::ResourceState::CopySrc, state}, {input, rhi::ResourceState::CopyDst, rhi::ResourceState::SampledRead}});
    rhi::Queue queue = device.queue();
    queue.submit(encoder.finish());
    queue.waitIdle();
}

} // namespace

extern "C" {

HUSH_API HushStatus hushCreateContextFromVulkan(const HushVulkanDevice* device, HushContext* context) {
    return guarded("hushCreateContextFromVulkan", [&] {
        required(context, "context");
        *context = nullptr;
        required(device, "device");
        if (!device->instance) badArgument("device->instance", "is VK_NULL_HANDLE");
        if (!device->physicalDevice) badArgument("device->physicalDevice", "is VK_NULL_HANDLE");
        if (!device->device) badArgument("device->device", "is VK_NULL_HANDLE");
        if (!device->queue) badArgument("device->queue", "is VK_NULL_HANDLE");
        auto made = std::make_unique<HushContext_T>();
        made->device = rhi::importVulkanDevice({.instance = device->instance,
                                                .physicalDevice = device->physicalDevice,
                                                .device = device->device,
                                                .queue = device->queue,
                                                .queueFamilyIndex = device->queueFamilyIndex,
                                                .getInstanceProcAddr = device->getInstanceProcAddr,
                                                .label = "hush-c.imported",
                                                .shaderStorageImageExtendedFormats =
                                                    device->shaderStorageImageExtendedFormats != 0});
        made->adapterName = made->device.adapterInfo().name;
        *context = made.release();
    });
}

HUSH_API VkFormat hushVulkanInputFormat(const char* name) {
    VkFormat format = VK_FORMAT_UNDEFINED;
    guarded("hushVulkanInputFormat", [&] {
        required(name, "name");
        const auto channel = passes::parseInputChannel(name);
        if (!channel) badArgument("name", std::string("'") + name + "' is not a frame-format layer");
        format = rhi::vulkanFormat(passes::inputChannelInfo(*channel).format);
    });
    return format;
}

HUSH_API HushStatus hushSetInputVulkanImage(HushDenoiser denoiser, const char* name, const HushVulkanImage* image) {
    return guarded("hushSetInputVulkanImage", [&] {
        HushDenoiser_T& d = *required(denoiser, "denoiser");
        const passes::InputChannel channel = capi::denoiserInput(d, name);
        required(image, "image");
        if (!image->image) badArgument("image->image", "is VK_NULL_HANDLE");
        const auto& info = passes::inputChannelInfo(channel);
        const VkFormat expected = rhi::vulkanFormat(info.format);
        if (image->format != expected)
            badArgument("image->format", "is VkFormat " + std::to_string(int(image->format)) + " for input '" + name +
                                             "', which is held as " + std::string(rhi::toString(info.format)) +
                                             " (VkFormat " + std::to_string(int(expected)) + ")");
        const auto size = d.runner->inputs().size();
        if (image->width != size.width || image->height != size.height)
            badArgument("image->width", "and 'image->height' are " + std::to_string(image->width) + "x" +
                                            std::to_string(image->height) + "; the denoiser is " +
                                            std::to_string(size.width) + "x" + std::to_string(size.height));
        const rhi::ResourceState state = stateOf(image->layout);
        const rhi::Texture source = rhi::wrapVulkanImage(
            d.context->device, image->image,
            {.label = std::string("engine.") + name, .size = size, .format = info.format, .usage = rhi::TextureUsage::CopySrc});
        copyIntoInput(d, channel, source, state);
        d.set[size_t(channel)] = true;
    });
}

} // extern "C"
