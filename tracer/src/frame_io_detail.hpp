#pragma once
// Private helpers shared by the frame writer, the frame reader and the BMFR dataset
// reader. Only src/ sees OpenEXR: the public headers stay free of it.
#include <cstdint>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include <Imath/ImathBox.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <hush/tracer/frame_io.hpp>

#include <hush/core/error.hpp>

namespace hush::tracer::detail {

// Header attribute names (docs/frame-format.md, "Header attributes"). All stay within
// 31 characters so that files need no "long names" flag and older readers cope.
inline constexpr const char* kAttrFormatVersion = "hush.formatVersion";
inline constexpr const char* kAttrFrameIndex = "hush.frameIndex";
inline constexpr const char* kAttrScene = "hush.scene";
inline constexpr const char* kAttrReferenceSpp = "hush.referenceSpp";
inline constexpr const char* kAttrMetresPerUnit = "hush.metresPerUnit";
inline constexpr const char* kCameraPrefix = "hush.camera.";
inline constexpr const char* kPreviousCameraPrefix = "hush.previousCamera.";
// Suffixes after either camera prefix.
inline constexpr const char* kCamView = "view";
inline constexpr const char* kCamProjection = "projection";
inline constexpr const char* kCamJitter = "jitter";
inline constexpr const char* kCamPosition = "position";
inline constexpr const char* kCamFov = "fov";
inline constexpr const char* kCamNear = "near";
inline constexpr const char* kCamFar = "far";

// Throws hush::Error naming `path` if it is missing, not a regular file, or does not
// start with the OpenEXR magic number. `what` says what the caller wanted ("frame").
// Checked up front because OpenEXR's own messages for these cases are obscure.
void checkExrFile(const std::string& path, std::string_view what);

// Walks the headers of the OpenEXR file open in `in` (just past its magic
// number) the way OpenEXR 3.1 reads it and refuses, with hush::Error starting with
// `prefix`, what would make OpenEXR allocate by a damaged size before noticing the
// damage: attribute sizes beyond the file, fixed-size types of another size, a
// channel list or preview that does not fill its attribute, a data window beyond
// 16384 pixels a side (exr_header_check.cpp).
void checkExrHeader(std::istream& in, std::uintmax_t fileSize, const std::string& prefix);

std::string boxText(const Imath::Box2i& box);   // "(0,0)-(12,6)"
std::string compressionName(Imf::Compression compression);

// A frame file's number from its name, "frame_0012.exr" -> 12; -1 if the name does
// not have that form (or the number does not fit 32 bits).
long long frameIndexFromFileName(std::string_view fileName);

// Blender Cycles multilayer files (frame_io_cycles.cpp, docs/blender.md): the view
// layer whose "<layer>.Combined.R" the header has ("" when none), and the frame made
// from its passes, added to `frame` (size and attributes already read).
std::string cyclesViewLayer(const Imf::Header& header);
std::vector<Channel> cyclesLayers(const Imf::Header& header, const std::string& viewLayer);   // from names alone
Frame readCyclesFrame(Imf::InputFile& file, const std::string& viewLayer, Frame frame, const ReadOptions& options,
                      const std::string& path);

} // namespace hush::tracer::detail
