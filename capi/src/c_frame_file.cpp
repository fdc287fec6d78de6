// The C API's frame-file readers (hush.h): one layer or the camera of a file in
// docs/frame-format.md, for C tools and tests.
#include <algorithm>
#include <cstring>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include <hush/tracer/frame_io.hpp>

#include "c_api_guard.hpp"

using namespace hush;
using capi::badArgument;
using capi::guarded;
using capi::required;

namespace {

// GLM stores column-major, as HushCamera does.
void copyMatrix(const glm::mat4& m, float (&out)[16]) { std::memcpy(out, glm::value_ptr(m), sizeof out); }

} // namespace

extern "C" {

HUSH_API HushStatus hushFrameFileSize(const char* path, uint32_t* width, uint32_t* height) {
    return guarded("hushFrameFileSize", [&] {
        required(path, "path");
        required(width, "width");
        required(height, "height");
        const tracer::FrameFileInfo info = tracer::readFrameInfo(path);
        *width = info.width;
        *height = info.height;
    });
}

HUSH_API HushStatus hushReadFrameLayer(const char* path, const char* layer, float* pixels, size_t count) {
    return guarded("hushReadFrameLayer", [&] {
        required(path, "path");
        required(layer, "layer");
        required(pixels, "pixels");
        const auto channel = tracer::parseChannel(layer);
        if (!channel) badArgument("layer", std::string("'") + layer + "' is not a frame-format layer (docs/frame-format.md)");
        const tracer::Frame frame = tracer::readFrame(path, {.channels = {*channel}});
        const auto& values = frame.get(*channel).pixels;
        if (count != values.size())
            badArgument("count", "is " + std::to_string(count) + "; layer '" + layer + "' of " + path + " holds " +
                                     std::to_string(values.size()) + " floats (" + std::to_string(frame.width) + "x" +
                                     std::to_string(frame.height) + "x" +
                                     std::to_string(tracer::channelInfo(*channel).components) + ")");
        std::copy(values.begin(), values.end(), pixels);
    });
}

HUSH_API HushStatus hushReadFrameCamera(const char* path, HushCamera* camera) {
    return guarded("hushReadFrameCamera", [&] {
        required(path, "path");
        required(camera, "camera");
        tracer::ReadOptions options;
        options.channels = {tracer::Channel::Depth};
        options.requireChannels = false;   // the header is what is wanted
        const tracer::Frame frame = tracer::readFrame(path, options);
        copyMatrix(frame.camera.view, camera->view);
        copyMatrix(frame.camera.projection, camera->projection);
        copyMatrix(frame.previousCamera.view, camera->previousView);
        copyMatrix(frame.previousCamera.projection, camera->previousProjection);
        for (int i = 0; i < 3; ++i) camera->position[i] = frame.camera.position[i];
        camera->metresPerUnit = frame.metresPerUnit;
    });
}

} // extern "C"
