#pragma once
// The viewer's frame files (docs/frame-format.md). FrameSource stands in for the
// engine's raster and ray passes: each frame's G-buffer and noisy radiance come from
// tracer frames on disk, already laid out as the texels of the engine's images, ready
// for a staging-buffer upload. writeDisplayFrame writes what the engine showed.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace viewer {

// Column-major 4x4 matrices, world -> view -> Vulkan clip space (docs/frame-format.md).
struct CameraMatrices {
    float view[16], projection[16], previousView[16], previousProjection[16];
    float position[3];
    float metresPerUnit = 1.0f;
};

struct SourceFrame {
    uint32_t index = 0;
    CameraMatrices camera{};
    std::map<std::string, std::vector<float>> texels;   // by layer name, texelFloats floats per pixel
};

// A layer the engine renders, and how many floats one texel of its image holds.
struct LayerLayout {
    std::string name;
    uint32_t texelFloats = 4;
};

class FrameSource {
public:
    // Reads frames [first, first + count) of `folder` (count 0: all). A layer the frames
    // lack is zero (emission, for renderers that do not split it off); throws
    // std::runtime_error naming the file otherwise.
    FrameSource(const std::string& folder, uint32_t first, uint32_t count, const std::vector<LayerLayout>& layers);

    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    const std::vector<SourceFrame>& frames() const { return frames_; }
    // The layers every frame file has, of those asked for.
    const std::vector<std::string>& present() const { return present_; }

private:
    uint32_t width_ = 0, height_ = 0;
    std::vector<SourceFrame> frames_;
    std::vector<std::string> present_;
};

// The frame at another size, as an engine rendering at that resolution would give it:
// each pixel the nearest source pixel's texels, motion scaled to the new pixels.
SourceFrame resampled(const SourceFrame& frame, uint32_t fromWidth, uint32_t fromHeight, uint32_t width,
                      uint32_t height, const std::vector<LayerLayout>& layers);

// Writes `rgba` (width * height * 4 floats) as frame `index` of `folder`
// (frame_<index>.exr, its rgb in the color layer, 32-bit float), atomically.
void writeDisplayFrame(const std::string& folder, uint32_t index, uint32_t width, uint32_t height, const float* rgba);

} // namespace viewer
