#pragma once
// Shared pieces of the node tests: float images on the CPU, uploading them as graph
// inputs, reading graph outputs back as floats, and comparing with a tolerance that
// the failure message spells out (worst pixel, its values, the tolerance).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <hush/graph/render_graph.hpp>
#include <hush/passes/node_context.hpp>
#include <hush/rhi/rhi.hpp>

#include "support/gpu_context.hpp"

namespace hush::passes_test {

using graph::TextureHandle;
using rhi::Format;

struct FloatImage {
    uint32_t width = 0, height = 0, channels = 0;
    std::vector<float> pixels;

    FloatImage() = default;
    FloatImage(uint32_t w, uint32_t h, uint32_t c, float fill = 0.0f)
        : width(w), height(h), channels(c), pixels(size_t(w) * h * c, fill) {}
    float& at(uint32_t x, uint32_t y, uint32_t c = 0) { return pixels[(size_t(y) * width + x) * channels + c]; }
    float at(uint32_t x, uint32_t y, uint32_t c = 0) const { return pixels[(size_t(y) * width + x) * channels + c]; }
    // Clamped to the image (edge texels repeat).
    float clamped(int x, int y, uint32_t c = 0) const;
};

// Uniform values in [lo, hi) from a fixed seed.
FloatImage randomImage(uint32_t width, uint32_t height, uint32_t channels, float lo, float hi, uint64_t seed);
// Fills pixel (x, y)'s channels with f(x, y, c).
FloatImage makeImage(uint32_t width, uint32_t height, uint32_t channels,
                     const std::function<float(uint32_t, uint32_t, uint32_t)>& f);

// An application-owned texture holding `image` (channels expanded to the format's;
// alpha 1), left in SampledRead state; TextureBinding, StorageBinding, Copy usages.
rhi::Texture uploadTexture(const FloatImage& image, Format format, const std::string& label);
// Any float format (fp16 converted) as floats, one per format channel.
FloatImage readTexture(const rhi::Texture& texture, rhi::ResourceState state);
// A graph output after graph.waitIdle().
FloatImage readOutput(const graph::RenderGraph& graph, TextureHandle output);
// Runs one frame and reads back `outputs` (already marked as outputs), in order.
std::vector<FloatImage> executeAndRead(graph::RenderGraph& graph, const std::vector<TextureHandle>& outputs);
std::vector<uint32_t> readOutputBuffer(const graph::RenderGraph& graph, graph::BufferHandle output);

// A graph, its pipelines and a NodeContext, on the shared test device.
struct NodeHarness {
    explicit NodeHarness(rhi::Extent2D size, const std::string& label = "node-test");
    passes::PipelineCache pipelines;
    graph::RenderGraph graph;
    passes::NodeContext ctx;
    // Uploads `image` and imports it as "<name>"; keeps the texture alive.
    TextureHandle input(const std::string& name, const FloatImage& image, Format format = Format::RGBA32Float);
    // Re-uploads an input made by input() (between frames).
    void update(const std::string& name, const FloatImage& image);
    // Marks `h` as output, executes one frame, waits, reads it back.
    FloatImage runOnce(TextureHandle h);

private:
    struct Imported {
        std::string name;
        rhi::Texture texture;
    };
    std::vector<Imported> imported_;
};

// Compares the first `channels` channels (0: all of a's) within
// |a - b| <= absTol + relTol * |b|; NaN anywhere fails. Returns "" when they match,
// else a message naming the worst pixel.
std::string compareImages(const FloatImage& gpu, const FloatImage& reference, float absTol, float relTol,
                          uint32_t channels = 0);
#define HUSH_REQUIRE_IMAGES_MATCH(gpu, ref, absTol, relTol, ...)                                     \
    do {                                                                                            \
        const std::string hush_diff_ = ::hush::passes_test::compareImages((gpu), (ref), (absTol),   \
                                                                          (relTol), ##__VA_ARGS__); \
        INFO(hush_diff_);                                                                           \
        REQUIRE(hush_diff_.empty());                                                                \
    } while (false)

// Counts non-finite values.
size_t nonFiniteCount(const FloatImage& image);

} // namespace hush::passes_test
