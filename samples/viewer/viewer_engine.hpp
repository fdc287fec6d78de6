#pragma once
// The engine's renderer, as far as the viewer needs one: it owns the G-buffer and
// radiance images hush reads and the two display images hush writes, fills the
// inputs each frame from its staging buffer (its "raster pass"), and reads a display
// image back for headless runs. Raw Vulkan only; hush is in viewer_denoiser.
#include <map>
#include <string>
#include <vector>

#include "engine_vulkan.hpp"
#include "frame_files.hpp"

namespace viewer {

// What one frame in flight owns: its command buffer, fence and staging memory.
struct FrameSlot {
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;   // created signalled
    EngineBuffer staging;             // every input layer of one frame, back to back
    EngineBuffer readback;            // the denoised display, RGBA32F
    bool hushPending = false;         // a hush frame recorded here awaits frameCompleted()
};

class ViewerEngine {
public:
    // `layers`: each layer the engine renders with its image format and texel size.
    ViewerEngine(EngineVulkan& vulkan, uint32_t width, uint32_t height, const std::vector<LayerLayout>& layers,
                 const std::map<std::string, VkFormat>& formats, VkFormat displayFormat, uint32_t slots);
    ~ViewerEngine();

    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    const std::map<std::string, EngineImage>& inputs() const { return inputs_; }
    const EngineImage& denoised() const { return denoised_; }
    const EngineImage& noisy() const { return noisy_; }
    FrameSlot& slot(uint64_t frame) { return slots_[frame % slots_.size()]; }

    // Waits for the slot's fence; begins its command buffer.
    void begin(FrameSlot& slot);
    // The "raster pass": the frame's layers into the input images, left in
    // SHADER_READ_ONLY_OPTIMAL for hush.
    void recordUpload(FrameSlot& slot, const SourceFrame& frame);
    // Copies the denoised display into the slot's readback buffer (headless runs).
    void recordReadback(FrameSlot& slot);
    // Ends and submits the command buffer (waiting on / signalling the given
    // semaphores, if any) with the slot's fence.
    void submit(FrameSlot& slot, VkSemaphore wait = VK_NULL_HANDLE, VkPipelineStageFlags2 waitStage = 0,
                VkSemaphore signal = VK_NULL_HANDLE);
    void waitIdle();

private:
    void initialLayouts();

    EngineVulkan& vulkan_;
    uint32_t width_, height_;
    std::vector<LayerLayout> layers_;
    std::map<std::string, EngineImage> inputs_;
    EngineImage denoised_, noisy_;
    std::vector<FrameSlot> slots_;
};

} // namespace viewer
