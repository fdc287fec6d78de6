#include "frame_files.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

#include <hush/core/error.hpp>
#include <hush/tracer/frame_io.hpp>

namespace viewer {
namespace {

void copyMatrix(const glm::mat4& m, float (&out)[16]) { std::memcpy(out, glm::value_ptr(m), sizeof out); }

CameraMatrices cameraOf(const hush::tracer::Frame& frame) {
    CameraMatrices c;
    copyMatrix(frame.camera.view, c.view);
    copyMatrix(frame.camera.projection, c.projection);
    copyMatrix(frame.previousCamera.view, c.previousView);
    copyMatrix(frame.previousCamera.projection, c.previousProjection);
    for (int i = 0; i < 3; ++i) c.position[i] = frame.camera.position[i];
    c.metresPerUnit = frame.metresPerUnit;
    return c;
}

// The frame's layer as the engine image's texels: its components, then zeros, with
// alpha 1 in four-float texels (what hush's own uploads do).
std::vector<float> texelsOf(const hush::tracer::Frame& frame, const LayerLayout& layer) {
    const size_t pixels = size_t(frame.width) * frame.height;
    std::vector<float> texels(pixels * layer.texelFloats, 0.0f);
    const auto channel = hush::tracer::parseChannel(layer.name);
    if (!channel || !frame.has(*channel)) return texels;
    const hush::tracer::Image& image = frame.get(*channel);
    const uint32_t copied = std::min(image.channels, layer.texelFloats);
    for (size_t p = 0; p < pixels; ++p) {
        std::memcpy(&texels[p * layer.texelFloats], &image.pixels[p * image.channels], copied * sizeof(float));
        if (layer.texelFloats == 4 && copied < 4) texels[p * 4 + 3] = 1.0f;
    }
    return texels;
}

} // namespace

FrameSource::FrameSource(const std::string& folder, uint32_t first, uint32_t count, const std::vector<LayerLayout>& layers) {
    try {
        const std::vector<std::string> files = hush::tracer::listFrames(folder);
        if (first >= files.size())
            throw std::runtime_error("'" + folder + "' holds " + std::to_string(files.size()) + " frames; --first is " +
                                     std::to_string(first));
        const size_t end = count ? std::min<size_t>(files.size(), size_t(first) + count) : files.size();
        for (size_t i = first; i < end; ++i) {
            hush::tracer::ReadOptions options;
            options.expectedWidth = width_, options.expectedHeight = height_;
            const hush::tracer::Frame frame = hush::tracer::readFrame(files[i], options);
            if (frames_.empty()) {
                width_ = frame.width, height_ = frame.height;
                for (const LayerLayout& layer : layers) {
                    const auto channel = hush::tracer::parseChannel(layer.name);
                    if (channel && frame.has(*channel)) present_.push_back(layer.name);
                }
            }
            SourceFrame source{frame.index, cameraOf(frame), {}};
            for (const LayerLayout& layer : layers) source.texels[layer.name] = texelsOf(frame, layer);
            frames_.push_back(std::move(source));
        }
    } catch (const hush::Error& e) {
        throw std::runtime_error(e.what());
    }
}

SourceFrame resampled(const SourceFrame& frame, uint32_t fromWidth, uint32_t fromHeight, uint32_t width,
                      uint32_t height, const std::vector<LayerLayout>& layers) {
    SourceFrame out{frame.index, frame.camera, {}};
    const float sx = float(width) / float(fromWidth), sy = float(height) / float(fromHeight);
    for (const LayerLayout& layer : layers) {
        const std::vector<float>& from = frame.texels.at(layer.name);
        std::vector<float>& to = out.texels[layer.name];
        to.resize(size_t(width) * height * layer.texelFloats);
        for (uint32_t y = 0; y < height; ++y)
            for (uint32_t x = 0; x < width; ++x) {
                const size_t src = (size_t(std::min(fromHeight - 1, uint32_t(float(y) / sy))) * fromWidth +
                                    std::min(fromWidth - 1, uint32_t(float(x) / sx))) * layer.texelFloats;
                float* texel = &to[(size_t(y) * width + x) * layer.texelFloats];
                std::copy_n(&from[src], layer.texelFloats, texel);
                if (layer.name == "motion") texel[0] *= sx, texel[1] *= sy;   // pixels of the new size
            }
    }
    return out;
}

void writeDisplayFrame(const std::string& folder, uint32_t index, uint32_t width, uint32_t height, const float* rgba) {
    try {
        hush::tracer::Frame frame;
        frame.width = width, frame.height = height, frame.index = index;
        frame.scene = "hush-viewer display";
        hush::tracer::Image& color = frame.add(hush::tracer::Channel::Color);
        for (size_t p = 0; p < size_t(width) * height; ++p)
            for (size_t c = 0; c < 3; ++c) color.pixels[p * 3 + c] = rgba[p * 4 + c];
        hush::tracer::writeFrame(frame, hush::tracer::framePath(folder, index), {.allFloat = true});
    } catch (const hush::Error& e) {
        throw std::runtime_error(e.what());
    }
}

} // namespace viewer
