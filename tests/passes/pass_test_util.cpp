#include "pass_test_util.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "support/half.hpp"

namespace hush::passes_test {

float FloatImage::clamped(int x, int y, uint32_t c) const {
    x = std::clamp(x, 0, int(width) - 1);
    y = std::clamp(y, 0, int(height) - 1);
    return at(uint32_t(x), uint32_t(y), c);
}

FloatImage randomImage(uint32_t width, uint32_t height, uint32_t channels, float lo, float hi, uint64_t seed) {
    FloatImage image(width, height, channels);
    test::Lcg lcg(seed);
    for (auto& v : image.pixels) v = lcg.uniform(lo, hi);
    return image;
}

FloatImage makeImage(uint32_t width, uint32_t height, uint32_t channels,
                     const std::function<float(uint32_t, uint32_t, uint32_t)>& f) {
    FloatImage image(width, height, channels);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x)
            for (uint32_t c = 0; c < channels; ++c) image.at(x, y, c) = f(x, y, c);
    return image;
}

namespace {
// `image` as the texture's texels: channels expanded to the format's (alpha 1), fp16
// converted.
std::vector<std::byte> texelBytes(const FloatImage& image, Format format) {
    const auto& info = rhi::formatInfo(format);
    REQUIRE((info.channelType == rhi::ChannelType::Float32 || info.channelType == rhi::ChannelType::Float16));
    std::vector<float> texels(size_t(image.width) * image.height * info.channels, 0.0f);
    for (size_t i = 0; i < size_t(image.width) * image.height; ++i)
        for (uint32_t c = 0; c < info.channels; ++c)
            texels[i * info.channels + c] =
                c < image.channels ? image.pixels[i * image.channels + c] : (c == 3 ? 1.0f : 0.0f);
    std::vector<std::byte> bytes;
    if (info.channelType == rhi::ChannelType::Float16) {
        std::vector<uint16_t> halves;
        for (float v : texels) halves.push_back(test::floatToHalf(v));
        const auto b = test::bytesOf(halves);
        bytes.assign(b.begin(), b.end());
    } else {
        const auto b = test::bytesOf(texels);
        bytes.assign(b.begin(), b.end());
    }
    return bytes;
}
} // namespace

rhi::Texture uploadTexture(const FloatImage& image, Format format, const std::string& label) {
    auto texture = test::gpu().device.createTexture(
        {.label = label,
         .size = {image.width, image.height},
         .format = format,
         .usage = rhi::TextureUsage::TextureBinding | rhi::TextureUsage::StorageBinding |
                  rhi::TextureUsage::CopySrc | rhi::TextureUsage::CopyDst});
    test::gpu().queue().writeTexture({.texture = texture,
                                      .data = texelBytes(image, format),
                                      .before = rhi::ResourceState::Undefined,
                                      .after = rhi::ResourceState::SampledRead});
    return texture;
}

FloatImage readTexture(const rhi::Texture& texture, rhi::ResourceState state) {
    const auto& info = rhi::formatInfo(texture.format());
    auto bytes = test::gpu().queue().readTexture({.texture = texture, .state = state});
    FloatImage image(texture.width(), texture.height(), info.channels);
    if (info.channelType == rhi::ChannelType::Float32) {
        image.pixels = test::valuesOf<float>(bytes);
    } else if (info.channelType == rhi::ChannelType::Float16) {
        auto halves = test::valuesOf<uint16_t>(bytes);
        for (size_t i = 0; i < halves.size(); ++i) image.pixels[i] = test::halfToFloat(halves[i]);
    } else if (info.channelType == rhi::ChannelType::Unorm8) {
        for (size_t i = 0; i < bytes.size(); ++i) image.pixels[i] = float(uint8_t(bytes[i])) / 255.0f;
    } else {
        auto words = test::valuesOf<uint32_t>(bytes);
        for (size_t i = 0; i < words.size(); ++i) image.pixels[i] = float(words[i]);
    }
    return image;
}

FloatImage readOutput(const graph::RenderGraph& graph, TextureHandle output) {
    return readTexture(graph.outputTexture(output), graph.outputState(output));
}

std::vector<FloatImage> executeAndRead(graph::RenderGraph& graph, const std::vector<TextureHandle>& outputs) {
    graph.execute();
    graph.waitIdle();
    std::vector<FloatImage> images;
    for (auto h : outputs) images.push_back(readOutput(graph, h));
    return images;
}

std::vector<uint32_t> readOutputBuffer(const graph::RenderGraph& graph, graph::BufferHandle output) {
    return test::valuesOf<uint32_t>(test::gpu().queue().readBuffer(graph.outputBuffer(output)));
}

NodeHarness::NodeHarness(rhi::Extent2D size, const std::string& label)
    : pipelines(test::gpu().device), graph(test::gpu().device, {.label = label}), ctx{graph, pipelines} {
    graph.setOutputSize(size);
}

TextureHandle NodeHarness::input(const std::string& name, const FloatImage& image, Format format) {
    auto texture = uploadTexture(image, format, name);
    imported_.push_back({name, texture});
    return graph.importTexture(name, texture);
}

void NodeHarness::update(const std::string& name, const FloatImage& image) {
    for (auto& i : imported_) {
        if (i.name != name) continue;
        graph.waitIdle();
        test::gpu().queue().writeTexture({.texture = i.texture,
                                          .data = texelBytes(image, i.texture.format()),
                                          .before = rhi::ResourceState::SampledRead,
                                          .after = rhi::ResourceState::SampledRead});
        return;
    }
    FAIL("no input called " << name);
}

FloatImage NodeHarness::runOnce(TextureHandle h) {
    graph.markOutput(h);
    graph.execute();
    graph.waitIdle();
    return readOutput(graph, h);
}

std::string compareImages(const FloatImage& gpu, const FloatImage& reference, float absTol, float relTol,
                          uint32_t channels) {
    std::ostringstream out;
    if (gpu.width != reference.width || gpu.height != reference.height) {
        out << "sizes differ: " << gpu.width << "x" << gpu.height << " vs " << reference.width << "x"
            << reference.height;
        return out.str();
    }
    if (channels == 0) channels = std::min(gpu.channels, reference.channels);
    if (channels > gpu.channels || channels > reference.channels) return "too few channels to compare";
    double worstExcess = -1.0;
    uint32_t wx = 0, wy = 0, wc = 0;
    size_t failures = 0;
    for (uint32_t y = 0; y < gpu.height; ++y)
        for (uint32_t x = 0; x < gpu.width; ++x)
            for (uint32_t c = 0; c < channels; ++c) {
                const float a = gpu.at(x, y, c), b = reference.at(x, y, c);
                const double tol = absTol + relTol * std::fabs(double(b));
                const double diff = std::fabs(double(a) - double(b));
                const bool bad = !std::isfinite(a) || !std::isfinite(b) || diff > tol;
                if (bad) ++failures;
                const double excess = bad && !std::isfinite(diff) ? 1e300 : diff - tol;
                if ((bad && excess > worstExcess) || (failures == 0 && excess > worstExcess)) {
                    worstExcess = excess;
                    wx = x, wy = y, wc = c;
                }
            }
    if (failures == 0) return {};
    out << failures << " values outside |gpu - ref| <= " << absTol << " + " << relTol << " * |ref|; worst at ("
        << wx << ", " << wy << ") channel " << wc << ": gpu " << gpu.at(wx, wy, wc) << ", reference "
        << reference.at(wx, wy, wc);
    return out.str();
}

size_t nonFiniteCount(const FloatImage& image) {
    return size_t(std::count_if(image.pixels.begin(), image.pixels.end(), [](float v) { return !std::isfinite(v); }));
}

} // namespace hush::passes_test
