#pragma once
// The viewer's window: GLFW, a Vulkan surface and swapchain, and the engine's present
// pass (a blit of hush's display images into the swapchain image). Keys become
// requests the main loop acts on. Raw Vulkan and GLFW only.
#include <string>
#include <vector>

#include "engine_vulkan.hpp"

struct GLFWwindow;

namespace viewer {

struct WindowRequests {
    int chain = -1;            // 0-based index of a chain key (1, 2, ...) pressed, else -1
    bool toggleSideBySide = false;
    int knob = 0;              // +1 / -1 for each '+' / '-' press
    bool resized = false;
};

class ViewerWindow {
public:
    ViewerWindow(uint32_t width, uint32_t height);   // glfwInit and the window
    ~ViewerWindow();
    // The instance extensions the window system needs (after construction).
    std::vector<const char*> instanceExtensions() const;
    void attach(EngineVulkan& vulkan);   // surface and swapchain
    void detach();                       // before the device goes

    bool shouldClose() const;
    WindowRequests poll();
    void setTitle(const std::string& title);
    // False when the swapchain had to be rebuilt (a resize): skip this frame's present.
    bool acquire(VkSemaphore available, uint32_t& image);
    // Blits `denoised` into the swapchain image, scaled to fill it (side by side: a split
    // screen, the noisy input's left half beside hush's right half), and leaves it ready
    // to present.
    void recordPresent(VkCommandBuffer cmd, uint32_t image, VkImage denoised, VkImage noisy, uint32_t width,
                       uint32_t height, bool sideBySide);
    void present(uint32_t image);
    void rebuild();   // the swapchain, at the window's new size
    VkExtent2D framebufferSize() const;
    VkSemaphore renderFinished(uint32_t image) const { return finished_[image]; }

private:
    void createSwapchain();
    void destroySwapchain();

    GLFWwindow* window_ = nullptr;
    EngineVulkan* vulkan_ = nullptr;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{};
    std::vector<VkImage> images_;
    std::vector<VkSemaphore> finished_;   // one per swapchain image
    WindowRequests pending_;
};

} // namespace viewer
