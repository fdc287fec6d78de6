#include "viewer_engine.hpp"

#include <cstring>
#include <stdexcept>

namespace viewer {
namespace {

constexpr VkImageUsageFlags kInputUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                          VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
constexpr VkImageUsageFlags kDisplayUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;

VkDeviceSize layerBytes(uint32_t width, uint32_t height, const LayerLayout& layer) {
    return VkDeviceSize(width) * height * layer.texelFloats * sizeof(float);
}

} // namespace

ViewerEngine::ViewerEngine(EngineVulkan& vulkan, uint32_t width, uint32_t height, const std::vector<LayerLayout>& layers,
                           const std::map<std::string, VkFormat>& formats, VkFormat displayFormat, uint32_t slots)
    : vulkan_(vulkan), width_(width), height_(height), layers_(layers), slots_(slots) {
    VkDeviceSize stagingBytes = 0;
    for (const LayerLayout& layer : layers_) {
        inputs_[layer.name] = vulkan_.createImage(width, height, formats.at(layer.name), kInputUsage);
        stagingBytes += layerBytes(width, height, layer);
    }
    denoised_ = vulkan_.createImage(width, height, displayFormat, kDisplayUsage);
    noisy_ = vulkan_.createImage(width, height, displayFormat, kDisplayUsage);
    for (FrameSlot& slot : slots_) {
        VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        poolInfo.queueFamilyIndex = vulkan_.queueFamily();
        check(vkCreateCommandPool(vulkan_.device(), &poolInfo, nullptr, &slot.pool), "vkCreateCommandPool");
        VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        alloc.commandPool = slot.pool;
        alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        alloc.commandBufferCount = 1;
        check(vkAllocateCommandBuffers(vulkan_.device(), &alloc, &slot.commands), "vkAllocateCommandBuffers");
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        check(vkCreateFence(vulkan_.device(), &fenceInfo, nullptr, &slot.fence), "vkCreateFence");
        slot.staging = vulkan_.createHostBuffer(stagingBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        slot.readback = vulkan_.createHostBuffer(VkDeviceSize(width) * height * 4 * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    }
    initialLayouts();
}

ViewerEngine::~ViewerEngine() {
    vkDeviceWaitIdle(vulkan_.device());
    for (FrameSlot& slot : slots_) {
        vulkan_.destroy(slot.staging);
        vulkan_.destroy(slot.readback);
        vkDestroyFence(vulkan_.device(), slot.fence, nullptr);
        vkDestroyCommandPool(vulkan_.device(), slot.pool, nullptr);
    }
    for (auto& [name, image] : inputs_) vulkan_.destroy(image);
    vulkan_.destroy(denoised_);
    vulkan_.destroy(noisy_);
}

// The layouts the engine keeps its images in between frames: inputs ready for
// shaders, display images ready to be copied or blitted from.
void ViewerEngine::initialLayouts() {
    FrameSlot& first = slots_[0];
    begin(first);
    for (auto& [name, image] : inputs_)
        transition(first.commands, image.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                   VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
    for (const EngineImage* image : {&denoised_, &noisy_})
        transition(first.commands, image->image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                   VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
    submit(first);
    waitIdle();
}

void ViewerEngine::begin(FrameSlot& slot) {
    check(vkWaitForFences(vulkan_.device(), 1, &slot.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    check(vkResetCommandBuffer(slot.commands, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(slot.commands, &info), "vkBeginCommandBuffer");
}

void ViewerEngine::recordUpload(FrameSlot& slot, const SourceFrame& frame) {
    VkDeviceSize offset = 0;
    for (const LayerLayout& layer : layers_) {
        const std::vector<float>& texels = frame.texels.at(layer.name);
        const VkDeviceSize bytes = layerBytes(width_, height_, layer);
        if (texels.size() * sizeof(float) != bytes) throw std::runtime_error("frame layer '" + layer.name + "' has the wrong size");
        std::memcpy(static_cast<char*>(slot.staging.mapped) + offset, texels.data(), bytes);
        const VkImage image = inputs_.at(layer.name).image;
        // Last frame's shader reads (hush's) finish before the copy overwrites.
        transition(slot.commands, image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{};
        region.bufferOffset = offset;
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {width_, height_, 1};
        vkCmdCopyBufferToImage(slot.commands, slot.staging.buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        transition(slot.commands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                   VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                   VK_ACCESS_2_SHADER_READ_BIT);
        offset += bytes;
    }
}

void ViewerEngine::recordReadback(FrameSlot& slot) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width_, height_, 1};
    vkCmdCopyImageToBuffer(slot.commands, denoised_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, slot.readback.buffer, 1, &region);
    VkMemoryBarrier2 toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    toHost.srcStageMask = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
    toHost.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    toHost.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    toHost.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &toHost;
    vkCmdPipelineBarrier2(slot.commands, &dependency);
}

void ViewerEngine::submit(FrameSlot& slot, VkSemaphore wait, VkPipelineStageFlags2 waitStage, VkSemaphore signal) {
    check(vkEndCommandBuffer(slot.commands), "vkEndCommandBuffer");
    check(vkResetFences(vulkan_.device(), 1, &slot.fence), "vkResetFences");
    VkCommandBufferSubmitInfo commands{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    commands.commandBuffer = slot.commands;
    VkSemaphoreSubmitInfo waitInfo{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    waitInfo.semaphore = wait;
    waitInfo.stageMask = waitStage;
    VkSemaphoreSubmitInfo signalInfo{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    signalInfo.semaphore = signal;
    signalInfo.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &commands;
    submit.waitSemaphoreInfoCount = wait ? 1 : 0;
    submit.pWaitSemaphoreInfos = &waitInfo;
    submit.signalSemaphoreInfoCount = signal ? 1 : 0;
    submit.pSignalSemaphoreInfos = &signalInfo;
    check(vkQueueSubmit2(vulkan_.queue(), 1, &submit, slot.fence), "vkQueueSubmit2");
}

void ViewerEngine::waitIdle() { check(vkQueueWaitIdle(vulkan_.queue()), "vkQueueWaitIdle"); }

} // namespace viewer
