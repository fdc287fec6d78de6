#pragma once
// Temporal artefacts no per-frame metric shows, measured against the references:
//  - ghosting: the error in pixels whose surface was disoccluded in the last few
//    frames, over the error elsewhere (a filter that drags history into newly seen
//    surfaces, or leaves them noisy, scores above the input's ratio);
//  - flicker: the temporal error between two consecutive outputs over the same
//    figure of their references (1: as steady as the truth; above: flickers).
// The disocclusion age is computed from the frames' G-buffer alone (motion, mesh id,
// depth), independently of any chain's own reprojection.
#include <cstdint>
#include <vector>

#include <hush/tracer/frame.hpp>

#include "display_image.hpp"

namespace hush::cli {

class DisocclusionAge {
public:
    // Frames a pixel's surface counts as newly seen after it appears.
    static constexpr uint8_t kRecentFrames = 4;

    // Follows each pixel to last frame through its motion vector (nearest pixel): the
    // age grows by one where last frame saw the same surface (mesh id equal, view depth
    // within 5 %), else it is 0. The first frame and a cut (`reset`) start every pixel at 0.
    void update(const tracer::Frame& frame, bool reset);
    // Pixels whose age is below kRecentFrames.
    std::vector<uint8_t> recentMask() const;

private:
    uint32_t width_ = 0, height_ = 0;
    std::vector<uint8_t> age_;
    std::vector<float> meshId_, depth_;
};

// RMSE over RGB between two display images, over the pixels where mask == inside.
// -1 when no pixel qualifies.
double maskedRmse(const RgbaImage& a, const RgbaImage& b, const std::vector<uint8_t>& mask, bool inside);

} // namespace hush::cli
