// writeFrame: a Frame -> one single-part scanline OpenEXR file, written to a
// temporary beside the target and renamed over it once complete.
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <vector>


#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>

#include <hush/core/atomic_file.hpp>
#include <hush/tracer/frame_io.hpp>

#include "frame_io_detail.hpp"

namespace hush::tracer {


namespace {

std::string layerText(Channel channel) { return "'" + std::string(channelInfo(channel).name) + "'"; }

// Everything that can be wrong with the Frame itself is found here, before any file is
// created, so such a failure can never touch the destination.
void validateFrame(const Frame& frame, const std::string& path) {
    const std::string prefix = "cannot write frame '" + path + "': ";
    if (frame.width == 0 || frame.height == 0)
        throw Error(ErrorKind::InvalidArgument, prefix + "the frame is empty (" + std::to_string(frame.width) + "x" +
                                                    std::to_string(frame.height) + ")");
    if (frame.width > uint32_t(std::numeric_limits<int>::max()) ||
        frame.height > uint32_t(std::numeric_limits<int>::max()))
        throw Error(ErrorKind::InvalidArgument, prefix + "the frame is too large for OpenEXR");
    if (frame.channels.empty()) throw Error(ErrorKind::InvalidArgument, prefix + "the frame has no channels");
    if (frame.index > uint32_t(std::numeric_limits<int>::max()) ||
        frame.referenceSpp > uint32_t(std::numeric_limits<int>::max()))
        throw Error(ErrorKind::InvalidArgument, prefix + "index or referenceSpp exceeds 2^31-1");
    if (!(std::isfinite(frame.metresPerUnit) && frame.metresPerUnit > 0.0f))
        throw Error(ErrorKind::InvalidArgument, prefix + "metresPerUnit must be finite and positive, got " +
                                                    std::to_string(frame.metresPerUnit));
    for (const auto& [channel, image] : frame.channels) {
        const uint32_t components = channelInfo(channel).components;
        if (image.width != frame.width || image.height != frame.height || image.channels != components ||
            image.pixels.size() != size_t(frame.width) * frame.height * components)
            throw Error(ErrorKind::InvalidArgument,
                        prefix + "channel " + layerText(channel) + " is " + std::to_string(image.width) + "x" +
                            std::to_string(image.height) + "x" + std::to_string(image.channels) + " with " +
                            std::to_string(image.pixels.size()) + " values, but the frame needs " +
                            std::to_string(frame.width) + "x" + std::to_string(frame.height) + "x" +
                            std::to_string(components));
    }
}

Imath::M44f toImath(const glm::mat4& m) {
    // Same 16 floats in the same order: glm's m[column][row] is Imath's x[row][column]
    // of the row-vector convention (v' = v * M), i.e. the same transform.
    Imath::M44f out;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out.x[i][j] = m[i][j];
    return out;
}

void addCamera(Imf::Header& header, const std::string& prefix, const CameraInfo& camera) {
    header.insert(prefix + detail::kCamView, Imf::M44fAttribute(toImath(camera.view)));
    header.insert(prefix + detail::kCamProjection, Imf::M44fAttribute(toImath(camera.projection)));
    header.insert(prefix + detail::kCamJitter, Imf::V2fAttribute(Imath::V2f(camera.jitter.x, camera.jitter.y)));
    header.insert(prefix + detail::kCamPosition,
                  Imf::V3fAttribute(Imath::V3f(camera.position.x, camera.position.y, camera.position.z)));
    header.insert(prefix + detail::kCamFov, Imf::FloatAttribute(camera.verticalFovDegrees));
    header.insert(prefix + detail::kCamNear, Imf::FloatAttribute(camera.nearPlane));
    header.insert(prefix + detail::kCamFar, Imf::FloatAttribute(camera.farPlane));
}

Imf::Compression toImf(ExrCompression compression) {
    switch (compression) {
    case ExrCompression::None: return Imf::NO_COMPRESSION;
    case ExrCompression::Piz: return Imf::PIZ_COMPRESSION;
    case ExrCompression::Zip: break;
    }
    return Imf::ZIP_COMPRESSION;
}

// Half conversion that keeps fireflies finite: a finite 1e6 becomes 65504, not +Inf,
// so a pass sees a bright pixel rather than a non-finite one the file did not have.
Imath::half toHalf(float value) {
    constexpr float kHalfMax = 65504.0f;
    if (std::isfinite(value)) value = std::fmax(-kHalfMax, std::fmin(kHalfMax, value));
    return Imath::half(value);
}

// Pixel data in the type the file stores, kept alive until writePixels is done.
// OutputFile does not convert between the frame buffer's type and the file's (unlike
// InputFile), so half and uint channels get converted copies; float ones are used in place.
struct Staging {
    std::vector<std::unique_ptr<Imath::half[]>> halves;
    std::vector<std::unique_ptr<uint32_t[]>> uints;
};

void addChannels(const Frame& frame, const WriteOptions& options, Imf::Header& header, Imf::FrameBuffer& buffer,
                 Staging& staging) {
    const size_t pixelCount = size_t(frame.width) * frame.height;
    for (const auto& [channel, image] : frame.channels) {
        const ChannelInfo& info = channelInfo(channel);
        PixelKind kind = info.storedAs;
        if (options.allFloat && kind == PixelKind::Half) kind = PixelKind::Float;
        const size_t n = info.components;
        for (size_t c = 0; c < n; ++c) {
            const std::string name = std::string(info.name) + "." + std::string(info.componentNames[c]);
            const float* source = image.pixels.data() + c;
            if (kind == PixelKind::Float) {
                header.channels().insert(name, Imf::Channel(Imf::FLOAT));
                // OutputFile only reads through the pointer; Slice wants a char*.
                buffer.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(source)),
                                               sizeof(float) * n, sizeof(float) * n * frame.width));
            } else if (kind == PixelKind::Half) {
                auto& data = staging.halves.emplace_back(new Imath::half[pixelCount]);
                for (size_t i = 0; i < pixelCount; ++i) data[i] = toHalf(source[i * n]);
                header.channels().insert(name, Imf::Channel(Imf::HALF));
                buffer.insert(name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(data.get()), sizeof(Imath::half),
                                               sizeof(Imath::half) * frame.width));
            } else {
                auto& data = staging.uints.emplace_back(new uint32_t[pixelCount]);
                for (size_t i = 0; i < pixelCount; ++i) data[i] = meshIdFromPixel(source[i * n]);
                header.channels().insert(name, Imf::Channel(Imf::UINT));
                buffer.insert(name, Imf::Slice(Imf::UINT, reinterpret_cast<char*>(data.get()), sizeof(uint32_t),
                                               sizeof(uint32_t) * frame.width));
            }
        }
    }
}

// Writes the whole file to `tempPath`; throws (any exception) on failure.
void writeExr(const Frame& frame, const std::string& tempPath, const WriteOptions& options) {
    // Header(w, h) sets both windows to (0,0)-(w-1,h-1) and INCREASING_Y: scanline y of
    // the file is row y of the Image, both counted from the top.
    Imf::Header header(int(frame.width), int(frame.height));
    header.compression() = toImf(options.compression);
    header.insert(detail::kAttrFormatVersion, Imf::IntAttribute(kFrameFormatVersion));
    header.insert(detail::kAttrFrameIndex, Imf::IntAttribute(int(frame.index)));
    header.insert(detail::kAttrScene, Imf::StringAttribute(frame.scene));
    header.insert(detail::kAttrReferenceSpp, Imf::IntAttribute(int(frame.referenceSpp)));
    header.insert(detail::kAttrMetresPerUnit, Imf::FloatAttribute(frame.metresPerUnit));
    addCamera(header, detail::kCameraPrefix, frame.camera);
    addCamera(header, detail::kPreviousCameraPrefix, frame.previousCamera);

    Imf::FrameBuffer buffer;
    Staging staging;
    addChannels(frame, options, header, buffer, staging);

    // Our own ofstream rather than OutputFile(path): OutputFile's destructor writes the
    // line offset table and swallows any error doing so, so only by checking the stream
    // after it is gone do we learn that the disk filled up at the very end.
    std::ofstream stream(tempPath, std::ios::binary | std::ios::trunc);
    if (!stream) throw std::runtime_error("cannot create '" + tempPath + "': " + std::strerror(errno));
    {
        Imf::StdOFStream exrStream(stream, tempPath.c_str());
        Imf::OutputFile file(exrStream, header);
        file.setFrameBuffer(buffer);
        file.writePixels(int(frame.height));
    }
    stream.flush();
    stream.close();
    if (!stream) throw std::runtime_error("writing '" + tempPath + "' failed: " + std::strerror(errno));
}

} // namespace

void writeFrame(const Frame& frame, const std::string& path, const WriteOptions& options) {
    validateFrame(frame, path);
    // Readers see the old file or the whole new one, never half of it.
    core::writeAtomically(path, [&](const std::string& temporary) { writeExr(frame, temporary, options); });
}

} // namespace hush::tracer
