// readFrame / readFrameInfo: an OpenEXR file (hush's own or another renderer's, per
// docs/frame-format.md) -> Frame. Layers are found by name; anything else is ignored.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>

#include <hush/tracer/frame_io.hpp>

#include "frame_io_detail.hpp"

namespace hush::tracer {

namespace {

// Builds "cannot read frame '<path>': ..." messages in one place.
struct Reader {
    const std::string& path;
    [[noreturn]] void fail(ErrorKind kind, const std::string& problem) const {
        throw Error(kind, "cannot read frame '" + path + "': " + problem);
    }
};

// The attribute `name` if present, after checking it has the type hush expects.
template <class Attribute>
const Attribute* find(const Imf::Header& header, const std::string& name, const Reader& reader) {
    const auto it = header.find(name);
    if (it == header.end()) return nullptr;
    const auto* typed = dynamic_cast<const Attribute*>(&it.attribute());
    if (!typed)
        reader.fail(ErrorKind::InvalidArgument, "header attribute '" + name + "' has type '" +
                                                    it.attribute().typeName() + "', expected '" +
                                                    Attribute::staticTypeName() + "'");
    return typed;
}

glm::mat4 toGlm(const Imath::M44f& m) {
    glm::mat4 out;   // the inverse of the writer's mapping: the same 16 floats in order
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out[i][j] = m.x[i][j];
    return out;
}

uint32_t readCount(const Imf::Header& header, const char* name, const Reader& reader, uint32_t fallback) {
    const auto* attribute = find<Imf::IntAttribute>(header, name, reader);
    if (!attribute) return fallback;
    if (attribute->value() < 0)
        reader.fail(ErrorKind::InvalidArgument,
                    "header attribute '" + std::string(name) + "' is negative (" +
                        std::to_string(attribute->value()) + ")");
    return uint32_t(attribute->value());
}

// Each attribute that is present overrides the matching field of `camera`.
void readCamera(const Imf::Header& header, const std::string& prefix, const Reader& reader, CameraInfo& camera) {
    if (const auto* a = find<Imf::M44fAttribute>(header, prefix + detail::kCamView, reader))
        camera.view = toGlm(a->value());
    if (const auto* a = find<Imf::M44fAttribute>(header, prefix + detail::kCamProjection, reader))
        camera.projection = toGlm(a->value());
    if (const auto* a = find<Imf::V2fAttribute>(header, prefix + detail::kCamJitter, reader))
        camera.jitter = glm::vec2(a->value().x, a->value().y);
    if (const auto* a = find<Imf::V3fAttribute>(header, prefix + detail::kCamPosition, reader))
        camera.position = glm::vec3(a->value().x, a->value().y, a->value().z);
    if (const auto* a = find<Imf::FloatAttribute>(header, prefix + detail::kCamFov, reader))
        camera.verticalFovDegrees = a->value();
    if (const auto* a = find<Imf::FloatAttribute>(header, prefix + detail::kCamNear, reader))
        camera.nearPlane = a->value();
    if (const auto* a = find<Imf::FloatAttribute>(header, prefix + detail::kCamFar, reader))
        camera.farPlane = a->value();
}

void readAttributes(const Imf::Header& header, const Reader& reader, Frame& frame) {
    const uint32_t version = readCount(header, detail::kAttrFormatVersion, reader, 1);
    if (version > uint32_t(kFrameFormatVersion))
        reader.fail(ErrorKind::Unsupported, "written in frame format version " + std::to_string(version) +
                                                ", this hush reads up to " + std::to_string(kFrameFormatVersion));
    // Without hush.frameIndex the name says it (frame_0012.exr), else 0.
    const long long fromName =
        detail::frameIndexFromFileName(std::filesystem::path(reader.path).filename().string());
    frame.index = readCount(header, detail::kAttrFrameIndex, reader, fromName >= 0 ? uint32_t(fromName) : 0);
    frame.referenceSpp = readCount(header, detail::kAttrReferenceSpp, reader, 0);
    if (const auto* a = find<Imf::StringAttribute>(header, detail::kAttrScene, reader)) frame.scene = a->value();
    if (const auto* a = find<Imf::FloatAttribute>(header, detail::kAttrMetresPerUnit, reader)) {
        if (!(std::isfinite(a->value()) && a->value() > 0.0f))
            reader.fail(ErrorKind::InvalidArgument, std::string(detail::kAttrMetresPerUnit) +
                                                        " must be finite and positive, got " + std::to_string(a->value()));
        frame.metresPerUnit = a->value();
    }
    readCamera(header, detail::kCameraPrefix, reader, frame.camera);
    // A missing previous camera (or part of one) is taken to be the current one: no motion.
    frame.previousCamera = frame.camera;
    readCamera(header, detail::kPreviousCameraPrefix, reader, frame.previousCamera);
}

PixelKind kindOf(Imf::PixelType type) {
    return type == Imf::UINT ? PixelKind::Uint : type == Imf::HALF ? PixelKind::Half : PixelKind::Float;
}

// The file's channels grouped by hush layer: layer -> component -> file channel.
// The error for a file from another renderer that has none of hush's layer names.
std::string noHushLayers(const Imf::Header& header) {
    std::string names;
    size_t count = 0;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it, ++count)
        if (count < 6) names += std::string(count ? ", " : "") + it.name();
    if (count > 6) names += ", ... (" + std::to_string(count) + " in all)";
    return "none of hush's layers (color, albedo, normal, depth, motion, ...) is present; the file's channels are " +
           (names.empty() ? std::string("none") : names) +
           ". docs/frame-format.md names the layers a renderer must write";
}

// Channels outside hush's layers (bare "R", "diffuse.R", "color.R" nested deeper)
// are not hush's and are skipped.
std::map<Channel, std::map<std::string, const Imf::Channel*>> hushLayers(const Imf::Header& header) {
    std::map<Channel, std::map<std::string, const Imf::Channel*>> layers;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        const std::string name = it.name();
        const size_t dot = name.find('.');
        if (dot == std::string::npos || name.find('.', dot + 1) != std::string::npos) continue;
        if (const auto channel = parseChannel(std::string_view(name).substr(0, dot)))
            layers[*channel][name.substr(dot + 1)] = &it.channel();
    }
    return layers;
}

std::string componentList(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& name : names) out += (out.empty() ? "" : ", ") + name;
    return out.empty() ? "none" : out;
}

// A hush layer must have exactly its components, unsubsampled.
void checkLayer(Channel channel, const std::map<std::string, const Imf::Channel*>& present, const Reader& reader) {
    const ChannelInfo& info = channelInfo(channel);
    std::vector<std::string> expected, found;
    for (uint32_t c = 0; c < info.components; ++c) expected.emplace_back(info.componentNames[c]);
    for (const auto& [component, exrChannel] : present) {
        found.push_back(component);
        if (exrChannel->xSampling != 1 || exrChannel->ySampling != 1)
            reader.fail(ErrorKind::Unsupported, "channel '" + std::string(info.name) + "." + component +
                                                    "' is subsampled; hush layers need one value per pixel");
    }
    std::vector<std::string> sortedExpected = expected;
    std::sort(sortedExpected.begin(), sortedExpected.end());
    if (found != sortedExpected)   // std::map keys are already sorted
        reader.fail(ErrorKind::InvalidArgument, "layer '" + std::string(info.name) + "' has " +
                                                    std::to_string(found.size()) + " component(s) (" +
                                                    componentList(found) + ") but hush expects " +
                                                    std::to_string(expected.size()) + " (" +
                                                    componentList(expected) + ")");
}

Imath::Box2i checkWindows(const Imf::Header& header, const ReadOptions& options, const Reader& reader) {
    const Imath::Box2i& data = header.dataWindow();
    const Imath::Box2i& display = header.displayWindow();
    // A cropped or padded data window would need a policy for the pixels outside it;
    // hush frames always cover the whole image, so other files are refused plainly.
    if (data != display)
        reader.fail(ErrorKind::Unsupported, "data window " + detail::boxText(data) + " differs from display window " +
                                                detail::boxText(display) + "; hush frames store the whole image");
    const long long width = (long long)data.max.x - data.min.x + 1, height = (long long)data.max.y - data.min.y + 1;
    if (width <= 0 || height <= 0)
        reader.fail(ErrorKind::InvalidArgument, "empty data window " + detail::boxText(data));
    if ((options.expectedWidth && width != options.expectedWidth) ||
        (options.expectedHeight && height != options.expectedHeight))
        reader.fail(ErrorKind::InvalidArgument,
                    "image is " + std::to_string(width) + "x" + std::to_string(height) + " (data window " +
                        detail::boxText(data) + "), expected " +
                        (options.expectedWidth ? std::to_string(options.expectedWidth) : "any") + "x" +
                        (options.expectedHeight ? std::to_string(options.expectedHeight) : "any"));
    return data;
}

Frame readExr(const std::string& path, const ReadOptions& options) {
    const Reader reader{path};
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    if (header.hasType() && Imf::isDeepData(header.type()))
        reader.fail(ErrorKind::Unsupported, "deep OpenEXR images are not frames");
    const Imath::Box2i window = checkWindows(header, options, reader);

    Frame frame;
    frame.width = uint32_t(window.max.x - window.min.x + 1);
    frame.height = uint32_t(window.max.y - window.min.y + 1);
    readAttributes(header, reader, frame);

    const auto layers = hushLayers(header);
    std::vector<Channel> wanted;
    for (Channel channel : options.channels)
        if (std::find(wanted.begin(), wanted.end(), channel) == wanted.end()) wanted.push_back(channel);
    if (wanted.empty())
        for (const auto& entry : layers) wanted.push_back(entry.first);
    if (layers.empty())   // another renderer's file: Blender Cycles' passes, or nothing hush knows
        if (const std::string viewLayer = detail::cyclesViewLayer(header); !viewLayer.empty())
            return detail::readCyclesFrame(file, viewLayer, std::move(frame), options, path);
    if (wanted.empty()) reader.fail(ErrorKind::NotFound, noHushLayers(header));
    Imf::FrameBuffer buffer;
    std::vector<std::vector<uint32_t>> meshIds;   // exact UINT ids, converted after reading
    for (Channel channel : wanted) {
        const ChannelInfo& info = channelInfo(channel);
        const auto layer = layers.find(channel);
        if (layer == layers.end()) {
            if (!options.requireChannels) continue;
            std::string present;
            for (const auto& entry : layers)
                present += std::string(present.empty() ? "" : ", ") + std::string(channelInfo(entry.first).name);
            reader.fail(ErrorKind::NotFound, "no layer '" + std::string(info.name) + "' (the file has: " +
                                                 (present.empty() ? "no hush layers" : present) + ")");
        }
        checkLayer(channel, layer->second, reader);
        Image& image = frame.add(channel);
        const size_t n = info.components;
        for (size_t c = 0; c < n; ++c) {
            const std::string name = std::string(info.name) + "." + std::string(info.componentNames[c]);
            const Imf::Channel* stored = layer->second.at(std::string(info.componentNames[c]));
            if (channel == Channel::MeshId && stored->type == Imf::UINT) {
                // Reading UINT into a FLOAT slice would round ids above 2^24 in OpenEXR's own way.
                auto& ids = meshIds.emplace_back(size_t(frame.width) * frame.height);
                buffer.insert(name, Imf::Slice::Make(Imf::UINT, ids.data(), window, sizeof(uint32_t),
                                                     sizeof(uint32_t) * frame.width));
            } else {
                // Half and float both land in float; InputFile converts half exactly.
                buffer.insert(name, Imf::Slice::Make(Imf::FLOAT, image.pixels.data() + c, window, sizeof(float) * n,
                                                     sizeof(float) * n * frame.width));
            }
        }
    }
    if (!file.isComplete())
        reader.fail(ErrorKind::InvalidArgument, "the file is truncated or damaged (some scanlines are missing)");
    file.setFrameBuffer(buffer);
    file.readPixels(window.min.y, window.max.y);

    if (frame.has(Channel::MeshId)) {
        std::vector<float>& pixels = frame.channels[Channel::MeshId].pixels;
        if (!meshIds.empty())
            for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = meshIdToPixel(meshIds[0][i]);
        else   // a foreign float id: normalise NaN, -5 or 2^32 to the canonical kNoMesh
            for (float& p : pixels) p = meshIdToPixel(meshIdFromPixel(p));
    }
    return frame;
}

} // namespace

Frame readFrame(const std::string& path, const ReadOptions& options) {
    detail::checkExrFile(path, "frame");
    try {
        return readExr(path, options);
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        // Past the magic-number check, OpenEXR failing means a damaged file (truncation,
        // corrupt compressed data...); its own words say where.
        throw Error(ErrorKind::InvalidArgument,
                    "cannot read frame '" + path + "': the file is damaged or truncated (OpenEXR: " + e.what() + ")");
    }
}

FrameFileInfo readFrameInfo(const std::string& path) {
    detail::checkExrFile(path, "frame");
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        FrameFileInfo info;
        const Imath::Box2i& window = header.dataWindow();
        info.width = uint32_t(std::max(0, window.max.x - window.min.x + 1));
        info.height = uint32_t(std::max(0, window.max.y - window.min.y + 1));
        info.compression = detail::compressionName(header.compression());
        for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
            info.exrChannels.push_back({it.name(), kindOf(it.channel().type)});
        for (const auto& entry : hushLayers(header)) info.layers.push_back(entry.first);
        if (const std::string viewLayer = detail::cyclesViewLayer(header); info.layers.empty() && !viewLayer.empty())
            info.layers = detail::cyclesLayers(header, viewLayer);   // what readFrame makes of its passes
        return info;
    } catch (const std::exception& e) {
        throw Error(ErrorKind::InvalidArgument, "cannot read frame '" + path + "': " + e.what());
    }
}

} // namespace hush::tracer
