#pragma once
// The integration layer: the only part of the viewer that knows hush. It imports the
// engine's VkDevice and images, builds the chosen chain into a render graph around
// them, and records it into the engine's command buffer each frame.
//
// The engine's images are imported in the layouts the engine keeps them in: inputs
// in SHADER_READ_ONLY_OPTIMAL, the two display images (denoised, noisy) in
// TRANSFER_SRC_OPTIMAL; hush leaves them there at the end of its commands.
#include <volk.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "frame_files.hpp"

namespace viewer {

struct EngineHandles {
    VkInstance instance;
    VkPhysicalDevice physicalDevice;
    VkDevice device;
    VkQueue queue;
    uint32_t queueFamily;
    bool extendedStorageFormats;
};

struct EngineImageRef {
    VkImage image;
    uint32_t width, height;
};

struct PassTime {
    std::string name;
    double ms;
};

class ViewerDenoiser {
public:
    explicit ViewerDenoiser(const EngineHandles& engine);
    ~ViewerDenoiser();

    // Every layer hush can read, with the format and texel size its image must have.
    static std::vector<LayerLayout> inputLayouts();
    static VkFormat inputFormat(const std::string& layer);
    static constexpr VkFormat kDisplayFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

    // The engine's images: `inputs` by layer name (those the frames carry, in `available`),
    // and the two RGBA32F display images hush writes.
    void setImages(const std::map<std::string, EngineImageRef>& inputs, const std::vector<std::string>& available,
                   EngineImageRef denoised, EngineImageRef noisy);
    // Lets go of the engine's images (and the graph over them) before the engine
    // destroys them, e.g. to render at a new size; every frame must be reported.
    void releaseImages();
    // A built-in chain's name, or a chain file's text ('{'...); rebuilds the graph (the
    // history starts over). Throws std::runtime_error with hush's message.
    void setChain(const std::string& chain);
    const std::string& chainName() const { return chainName_; }
    void setCamera(const CameraMatrices& camera);

    // Records one frame into the engine's command buffer (begun); the engine submits it
    // and calls frameCompleted() once its fence has signalled.
    void record(VkCommandBuffer commandBuffer);
    void frameCompleted();
    // The newest completed frame's GPU time per pass and in all (negative: none yet).
    std::vector<PassTime> passTimes() const;
    double frameMs() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::string chainName_;
};

} // namespace viewer
