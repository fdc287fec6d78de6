// The BMFR authors' dataset layout (separate RGB float EXRs per buffer and frame,
// cameras given apart) -> hush Frames. See bmfr_dataset.hpp for the layout.
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfInputFile.h>

#include <hush/tracer/bmfr_dataset.hpp>

#include "frame_io_detail.hpp"

namespace hush::tracer {

namespace fs = std::filesystem;

namespace {

std::string bmfrPath(const std::string& folder, const char* buffer, uint32_t index) {
    return (fs::path(folder) / (std::string(buffer) + std::to_string(index) + ".exr")).string();
}

// One RGB image into a 3-channel float Image; `width`/`height` 0 take the file's size.
Image readRgb(const std::string& path, uint32_t width, uint32_t height) {
    detail::checkExrFile(path, "BMFR image");
    const std::string prefix = "cannot read BMFR image '" + path + "': ";
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const long long w = (long long)window.max.x - window.min.x + 1, h = (long long)window.max.y - window.min.y + 1;
        if (w <= 0 || h <= 0)
            throw Error(ErrorKind::InvalidArgument, prefix + "empty data window " + detail::boxText(window));
        if (width && (w != width || h != height))
            throw Error(ErrorKind::InvalidArgument, prefix + "it is " + std::to_string(w) + "x" + std::to_string(h) +
                                                        " but the frame's other buffers are " + std::to_string(width) +
                                                        "x" + std::to_string(height));
        Image image(uint32_t(w), uint32_t(h), 3);
        Imf::FrameBuffer buffer;
        const char* names[] = {"R", "G", "B"};
        for (size_t c = 0; c < 3; ++c) {
            const Imf::Channel* channel = file.header().channels().findChannel(names[c]);
            if (!channel)
                throw Error(ErrorKind::InvalidArgument, prefix + "no channel '" + names[c] + "' (BMFR images are RGB)");
            if (channel->xSampling != 1 || channel->ySampling != 1)
                throw Error(ErrorKind::Unsupported, prefix + "channel '" + names[c] + "' is subsampled");
            buffer.insert(names[c], Imf::Slice::Make(Imf::FLOAT, image.pixels.data() + c, window, 3 * sizeof(float),
                                                     3 * sizeof(float) * image.width));
        }
        if (!file.isComplete()) throw Error(ErrorKind::InvalidArgument, prefix + "the file is truncated or damaged");
        file.setFrameBuffer(buffer);
        file.readPixels(window.min.y, window.max.y);
        return image;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(ErrorKind::InvalidArgument, prefix + e.what());
    }
}

// The authors' color<N>.exr is illumination with the first-bounce albedo already
// removed (Sec. 3: "Before inputting the 1 spp input into our post-processing
// pipeline, we remove first bounce surface albedo from it"; their kernels multiply by
// albedo at the end and never divide). hush's `color` is full radiance, which its
// chains demodulate themselves, so the albedo is put back here.
void remodulate(Image& illumination, const Image& albedo) {
    for (size_t i = 0; i < illumination.pixels.size(); ++i) illumination.pixels[i] *= albedo.pixels[i];
}

} // namespace

BmfrCameraData readBmfrCameraFile(const std::string& path) {
    std::ifstream in(path);
    if (!in)
        throw Error(ErrorKind::NotFound, "cannot read BMFR camera file '" + path + "': no such file or not readable");
    BmfrCameraData data;
    std::string line;
    for (size_t lineNumber = 1; std::getline(in, line); ++lineNumber) {
        const std::string where = "BMFR camera file '" + path + "' line " + std::to_string(lineNumber) + ": ";
        for (char& c : line)
            if (c == ',' || c == '\t' || c == '\r') c = ' ';
        std::vector<float> values;
        size_t pos = line.find_first_not_of(' ');
        if (pos == std::string::npos || line[pos] == '#') continue;
        while (pos != std::string::npos) {
            const size_t end = std::min(line.find(' ', pos), line.size());
            float value = 0.0f;
            const auto [stop, ec] = std::from_chars(line.data() + pos, line.data() + end, value);
            if (ec != std::errc() || stop != line.data() + end || !std::isfinite(value))
                throw Error(ErrorKind::InvalidArgument,
                            where + "'" + line.substr(pos, end - pos) + "' is not a finite number");
            values.push_back(value);
            pos = line.find_first_not_of(' ', end);
        }
        if (values.size() != 16 && values.size() != 18)
            throw Error(ErrorKind::InvalidArgument,
                        where + "expected 16 numbers (the view-projection matrix, row-major) or 18 (plus the "
                                "jitter), found " + std::to_string(values.size()));
        glm::mat4 m;
        for (int row = 0; row < 4; ++row)
            for (int column = 0; column < 4; ++column) m[column][row] = values[size_t(row * 4 + column)];
        data.viewProjection.push_back(m);
        data.jitter.push_back(values.size() == 18 ? glm::vec2(values[16], values[17]) : glm::vec2(0.0f));
    }
    if (in.bad()) throw Error(ErrorKind::InvalidArgument, "cannot read BMFR camera file '" + path + "': read error");
    if (data.viewProjection.empty())
        throw Error(ErrorKind::InvalidArgument, "BMFR camera file '" + path + "' holds no cameras");
    return data;
}

Frame readBmfrFrame(const std::string& folder, uint32_t index, const BmfrCameraData* camera) {
    if (camera && (index >= camera->viewProjection.size() || camera->jitter.size() != camera->viewProjection.size()))
        throw Error(ErrorKind::InvalidArgument, "BMFR frame " + std::to_string(index) + " of '" + folder +
                                                    "': the camera data has " +
                                                    std::to_string(camera->viewProjection.size()) + " frames");
    Frame frame;
    frame.index = index;
    frame.scene = fs::path(folder).filename().string();
    if (frame.scene.empty()) frame.scene = fs::path(folder).parent_path().filename().string();   // "dir/"

    const struct {
        const char* file;
        Channel channel;
    } buffers[] = {{"color", Channel::Color},
                   {"shading_normal", Channel::Normal},
                   {"world_position", Channel::Position},
                   {"albedo", Channel::Albedo}};
    for (const auto& buffer : buffers) {
        Image image = readRgb(bmfrPath(folder, buffer.file, index), frame.width, frame.height);
        frame.width = image.width;
        frame.height = image.height;
        frame.channels[buffer.channel] = std::move(image);
    }
    remodulate(frame.channels[Channel::Color], frame.channels[Channel::Albedo]);
    const std::string reference = bmfrPath(folder, "reference", index);
    std::error_code ec;
    if (fs::exists(reference, ec)) frame.channels[Channel::Reference] = readRgb(reference, frame.width, frame.height);

    if (camera) {
        frame.camera.view = glm::mat4(1.0f);
        frame.camera.projection = camera->viewProjection[index];
        frame.camera.jitter = camera->jitter[index];
        frame.previousCamera = frame.camera;
        if (index > 0) {
            frame.previousCamera.projection = camera->viewProjection[index - 1];
            frame.previousCamera.jitter = camera->jitter[index - 1];
        }
    }
    return frame;
}

uint32_t countBmfrFrames(const std::string& folder) {
    uint32_t count = 0;
    std::error_code ec;
    while (fs::is_regular_file(bmfrPath(folder, "color", count), ec)) ++count;
    return count;
}

} // namespace hush::tracer
