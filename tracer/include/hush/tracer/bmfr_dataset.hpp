#pragma once
// Reading the BMFR authors' dataset layout (Koskela et al. 2019, seed 002) so their
// kind of data can be denoised by hush. Per frame N (from 0) a folder holds separate
// 3-channel float OpenEXR files, channels "R", "G", "B":
//   color<N>.exr           1-spp noisy illumination, albedo removed (Sec. 3)
//                          -> Channel::Color = illumination * albedo (full radiance)
//   shading_normal<N>.exr  world-space shading normal -> Channel::Normal
//   world_position<N>.exr  world-space position       -> Channel::Position
//   albedo<N>.exr          primary-hit albedo         -> Channel::Albedo
//   reference<N>.exr       optional (hush's addition): the many-spp reference -> Channel::Reference
// N is written without padding (color0.exr, color12.exr). The camera is not in the
// images; it comes separately (readBmfrCameraFile). docs/frame-format.md has details.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <hush/tracer/frame.hpp>

namespace hush::tracer {

struct BmfrCameraData {
    std::vector<glm::mat4> viewProjection;   // per frame: world -> clip
    std::vector<glm::vec2> jitter;           // per frame, pixels; zero where the file gives none
};

// A text camera file: one line per frame, frame 0 first. Each line holds 16 numbers,
// the view-projection matrix in row-major order (m00 m01 m02 m03 m10 ... m33, for
// clip = M * (x, y, z, 1) with column vectors), optionally followed by 2 numbers, the
// frame's subpixel jitter in pixels. Numbers are separated by spaces, tabs or commas;
// blank lines and lines starting with '#' are skipped. Throws hush::Error naming the
// file and line of anything else.
BmfrCameraData readBmfrCameraFile(const std::string& path);

// Frame `index` of a BMFR-layout folder. With `camera`, the frame's camera has
// view = identity and projection = that frame's view-projection (so projection * view
// is the full transform, which is all reprojection needs), jitter from the file, and
// previousCamera = frame index-1's (frame 0: its own). Without it both are default.
// All files must have the same size. Throws hush::Error naming the file at fault.
Frame readBmfrFrame(const std::string& folder, uint32_t index, const BmfrCameraData* camera = nullptr);

// How many consecutive frames (color0.exr, color1.exr, ...) the folder holds; 0 if none.
uint32_t countBmfrFrames(const std::string& folder);

} // namespace hush::tracer
