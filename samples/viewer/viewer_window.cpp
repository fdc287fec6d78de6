#include "viewer_window.hpp"

#include <algorithm>
#include <stdexcept>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace viewer {
namespace {

void onKey(GLFWwindow* window, int key, int, int action, int) {
    if (action != GLFW_PRESS) return;
    auto& requests = *static_cast<WindowRequests*>(glfwGetWindowUserPointer(window));
    if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9) requests.chain = key - GLFW_KEY_1;
    if (key == GLFW_KEY_S) requests.toggleSideBySide = true;
    if (key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD) ++requests.knob;
    if (key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT) --requests.knob;
    if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) glfwSetWindowShouldClose(window, GLFW_TRUE);
}

void onResize(GLFWwindow* window, int, int) {
    static_cast<WindowRequests*>(glfwGetWindowUserPointer(window))->resized = true;
}

} // namespace

ViewerWindow::ViewerWindow(uint32_t width, uint32_t height) {
    if (!glfwInit()) throw std::runtime_error("glfwInit failed: no display? (use --headless, or run under Xvfb)");
    if (!glfwVulkanSupported()) throw std::runtime_error("GLFW finds no Vulkan loader");
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    window_ = glfwCreateWindow(int(width), int(height), "hush viewer", nullptr, nullptr);
    if (!window_) throw std::runtime_error("glfwCreateWindow failed");
    glfwSetWindowUserPointer(window_, &pending_);
    glfwSetKeyCallback(window_, onKey);
    glfwSetFramebufferSizeCallback(window_, onResize);
}

ViewerWindow::~ViewerWindow() {
    detach();
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

std::vector<const char*> ViewerWindow::instanceExtensions() const {
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    return {names, names + count};
}

void ViewerWindow::attach(EngineVulkan& vulkan) {
    vulkan_ = &vulkan;
    check(glfwCreateWindowSurface(vulkan.instance(), window_, nullptr, &surface_), "glfwCreateWindowSurface");
    VkBool32 supported = VK_FALSE;
    check(vkGetPhysicalDeviceSurfaceSupportKHR(vulkan.physicalDevice(), vulkan.queueFamily(), surface_, &supported),
          "vkGetPhysicalDeviceSurfaceSupportKHR");
    if (!supported) throw std::runtime_error("the adapter's queue cannot present to this window");
    createSwapchain();
}

void ViewerWindow::detach() {
    if (!vulkan_) return;
    vkDeviceWaitIdle(vulkan_->device());
    destroySwapchain();
    if (surface_) vkDestroySurfaceKHR(vulkan_->instance(), surface_, nullptr);
    surface_ = VK_NULL_HANDLE;
    vulkan_ = nullptr;
}

void ViewerWindow::createSwapchain() {
    VkSurfaceCapabilitiesKHR caps;
    check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(vulkan_->physicalDevice(), surface_, &caps), "surface capabilities");
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw std::runtime_error("the swapchain cannot be a blit destination on this adapter");
    uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(vulkan_->physicalDevice(), surface_, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(vulkan_->physicalDevice(), surface_, &count, formats.data());
    VkSurfaceFormatKHR chosen = formats.at(0);
    for (const auto& f : formats)   // hush's display is linear: an sRGB swapchain encodes it
        if (f.format == VK_FORMAT_B8G8R8A8_SRGB || f.format == VK_FORMAT_R8G8B8A8_SRGB) chosen = f;
    format_ = chosen.format;
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    extent_ = caps.currentExtent.width != UINT32_MAX ? caps.currentExtent : VkExtent2D{uint32_t(w), uint32_t(h)};
    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface_;
    info.minImageCount = std::max(2u, caps.minImageCount);
    if (caps.maxImageCount) info.minImageCount = std::min(info.minImageCount, caps.maxImageCount);
    info.imageFormat = chosen.format;
    info.imageColorSpace = chosen.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
    info.clipped = VK_TRUE;
    check(vkCreateSwapchainKHR(vulkan_->device(), &info, nullptr, &swapchain_), "vkCreateSwapchainKHR");
    vkGetSwapchainImagesKHR(vulkan_->device(), swapchain_, &count, nullptr);
    images_.resize(count);
    vkGetSwapchainImagesKHR(vulkan_->device(), swapchain_, &count, images_.data());
    finished_.resize(count);
    for (VkSemaphore& s : finished_) {
        VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        check(vkCreateSemaphore(vulkan_->device(), &semaphore, nullptr, &s), "vkCreateSemaphore");
    }
}

void ViewerWindow::destroySwapchain() {
    for (VkSemaphore s : finished_) vkDestroySemaphore(vulkan_->device(), s, nullptr);
    finished_.clear();
    images_.clear();
    if (swapchain_) vkDestroySwapchainKHR(vulkan_->device(), swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
}

bool ViewerWindow::shouldClose() const { return glfwWindowShouldClose(window_); }

WindowRequests ViewerWindow::poll() {
    glfwPollEvents();
    const WindowRequests requests = pending_;
    pending_ = {};
    return requests;
}

VkExtent2D ViewerWindow::framebufferSize() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {uint32_t(std::max(w, 0)), uint32_t(std::max(h, 0))};
}

void ViewerWindow::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

bool ViewerWindow::acquire(VkSemaphore available, uint32_t& image) {
    const VkResult result = vkAcquireNextImageKHR(vulkan_->device(), swapchain_, UINT64_MAX, available, VK_NULL_HANDLE, &image);
    if (result == VK_ERROR_OUT_OF_DATE_KHR) {
        rebuild();
        return false;
    }
    if (result != VK_SUBOPTIMAL_KHR) check(result, "vkAcquireNextImageKHR");
    return true;
}

void ViewerWindow::recordPresent(VkCommandBuffer cmd, uint32_t image, VkImage denoised, VkImage noisy, uint32_t width,
                                 uint32_t height, bool sideBySide) {
    const VkImage target = images_[image];
    transition(cmd, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
               0, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    const int32_t w = int32_t(extent_.width), h = int32_t(extent_.height);
    // Source columns [s0, s1) of `source` to window columns [d0, d1), full height.
    const auto blit = [&](VkImage source, int32_t s0, int32_t s1, int32_t d0, int32_t d1) {
        VkImageBlit region{};
        region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.srcOffsets[0] = {s0, 0, 0};
        region.srcOffsets[1] = {s1, int32_t(height), 1};
        region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.dstOffsets[0] = {d0, 0, 0};
        region.dstOffsets[1] = {d1, h, 1};
        // Nearest: float formats need not support linear filtering in blits.
        vkCmdBlitImage(cmd, source, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                       &region, VK_FILTER_NEAREST);
    };
    const int32_t half = int32_t(width) / 2;
    if (sideBySide) {   // a split screen: the noisy input's left half, hush's right half
        blit(noisy, 0, half, 0, w * half / int32_t(width));
        blit(denoised, half, int32_t(width), w * half / int32_t(width), w);
    } else {
        blit(denoised, 0, int32_t(width), 0, w);
    }
    transition(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
               VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_NONE, 0);
}

void ViewerWindow::present(uint32_t image) {
    VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &finished_[image];
    info.swapchainCount = 1;
    info.pSwapchains = &swapchain_;
    info.pImageIndices = &image;
    const VkResult result = vkQueuePresentKHR(vulkan_->queue(), &info);
    if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) return rebuild();
    check(result, "vkQueuePresentKHR");
}

void ViewerWindow::rebuild() {
    vkDeviceWaitIdle(vulkan_->device());
    destroySwapchain();
    createSwapchain();
}

} // namespace viewer
