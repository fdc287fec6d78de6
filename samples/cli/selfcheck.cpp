// CPU reference and GPU run of shaders/rhi/selfcheck.comp.
#include "selfcheck.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <hush/rhi/rhi.hpp>
#include <hush_cli_shaders.hpp>

namespace hush::cli {
namespace {

using namespace hush::rhi;

// Odd sizes, so the dispatch's rounded-up edge invocations are exercised too.
constexpr uint32_t kWidth = 67;
constexpr uint32_t kHeight = 45;
constexpr float kA = 1.5f;
// The GPU may fuse a*x+y into one rounding (fma) where the CPU rounds twice: a
// few ulps of float32 either way; anything larger is a real failure.
constexpr double kTolerance = 1e-5;

struct Params {   // the shader's push constants
    float a;
    uint32_t n;
};

// Compare one value; NaN from the GPU counts as an infinite error.
double relativeError(float gpu, float cpu) {
    double error = std::fabs(double(gpu) - double(cpu)) / std::max(1.0, std::fabs(double(cpu)));
    return std::isnan(error) ? std::numeric_limits<double>::infinity() : error;
}

template <class T>
std::vector<T> fromBytes(const std::vector<std::byte>& bytes) {
    std::vector<T> out(bytes.size() / sizeof(T));
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
    return out;
}

} // namespace

bool SelfCheckResult::passed() const {
    // Written as "<=" so that NaN or infinity fails.
    return bufferMaxError <= tolerance && imageMaxError <= tolerance;
}

SelfCheckResult runSelfCheck(const Device& device) {
    const uint32_t n = kWidth * kHeight;

    // Inputs: deterministic, of mixed sign and magnitude.
    std::vector<float> x(n), y(n), image(size_t(n) * 4);
    for (uint32_t i = 0; i < n; ++i) {
        x[i] = std::sin(float(i) * 0.37f) * 4.0f;
        y[i] = float(i % 97) * 0.25f - 8.0f;
        image[4 * i + 0] = std::cos(float(i) * 0.11f) * 2.0f;
        image[4 * i + 1] = float(i % 13) * -0.5f;
        image[4 * i + 2] = 1.0f / float(1 + i % 7);
        image[4 * i + 3] = float(i % 5) * 0.2f;
    }

    ShaderModule module = device.createShaderModule(
        {.label = "rhi/selfcheck", .code = hush::cli_shaders::find("rhi/selfcheck")});
    ComputePipeline pipeline = device.createComputePipeline({.label = "rhi/selfcheck", .module = module});

    Buffer xBuffer = device.createBuffer(
        {.label = "selfcheck.x", .size = n * sizeof(float), .usage = BufferUsage::Storage | BufferUsage::CopyDst});
    Buffer yBuffer = device.createBuffer({.label = "selfcheck.y",
                                          .size = n * sizeof(float),
                                          .usage = BufferUsage::Storage | BufferUsage::CopyDst | BufferUsage::CopySrc});
    Texture texture = device.createTexture(
        {.label = "selfcheck.image",
         .size = {kWidth, kHeight},
         .format = Format::RGBA32Float,
         .usage = TextureUsage::StorageBinding | TextureUsage::CopyDst | TextureUsage::CopySrc});

    Queue queue = device.queue();
    queue.writeBuffer(xBuffer, 0, std::as_bytes(std::span(x)));
    queue.writeBuffer(yBuffer, 0, std::as_bytes(std::span(y)));
    queue.writeTexture({.texture = texture,
                        .data = std::as_bytes(std::span(image)),
                        .before = ResourceState::Undefined,
                        .after = ResourceState::StorageReadWrite});

    BindGroup group = device.createBindGroup({.label = "selfcheck",
                                              .layout = pipeline.getBindGroupLayout(0),
                                              .entries = {{.binding = 0, .buffer = xBuffer},
                                                          {.binding = 1, .buffer = yBuffer},
                                                          {.binding = 2, .texture = texture}}});

    const bool timed = device.adapterInfo().limits.timestampsSupported;
    QuerySet timestamps;
    if (timed) {
        timestamps = device.createQuerySet({.label = "selfcheck", .count = 2});
    }

    CommandEncoder encoder = device.createCommandEncoder({.label = "selfcheck"});
    // The uploads above were copies; make them visible to the shader.
    encoder.bufferBarrier({{xBuffer, ResourceState::CopyDst, ResourceState::StorageRead},
                           {yBuffer, ResourceState::CopyDst, ResourceState::StorageReadWrite}});
    ComputePassDesc passDesc{.label = "selfcheck"};
    if (timed) {
        encoder.resetQuerySet(timestamps, 0, 2);
        passDesc.timestampWrites = {.querySet = timestamps, .beginIndex = 0, .endIndex = 1};
    }
    ComputePassEncoder pass = encoder.beginComputePass(passDesc);
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, group);
    pass.setParams(Params{kA, n});
    pass.dispatchThreads(kWidth, kHeight);
    pass.end();
    // The read-back below copies out of y.
    encoder.bufferBarrier({{yBuffer, ResourceState::StorageReadWrite, ResourceState::CopySrc}});
    queue.wait(queue.submit(encoder.finish()));

    std::vector<float> yGpu = fromBytes<float>(queue.readBuffer(yBuffer));
    std::vector<float> imageGpu =
        fromBytes<float>(queue.readTexture({.texture = texture, .state = ResourceState::StorageReadWrite}));

    SelfCheckResult result{.width = kWidth, .height = kHeight, .tolerance = kTolerance};
    if (timed) {
        result.gpuMs = timestamps.elapsedMs(0, 1);
    }
    if (yGpu.size() != n || imageGpu.size() != image.size()) {
        throw Error(ErrorKind::Driver, "self-check: read back " + std::to_string(yGpu.size()) + " floats of y and " +
                                           std::to_string(imageGpu.size()) + " of the image, expected " +
                                           std::to_string(n) + " and " + std::to_string(image.size()));
    }
    for (uint32_t i = 0; i < n; ++i) {
        float expected = kA * x[i] + y[i];
        result.bufferMaxError = std::max(result.bufferMaxError, relativeError(yGpu[i], expected));
    }
    for (uint32_t py = 0; py < kHeight; ++py) {
        for (uint32_t px = 0; px < kWidth; ++px) {
            size_t t = 4 * (size_t(py) * kWidth + px);
            float expected[4] = {image[t + 0] * kA + float(px), image[t + 1] * kA + float(py),
                                 image[t + 2] * kA + 1.0f, image[t + 3] * image[t + 3]};
            for (int c = 0; c < 4; ++c) {
                result.imageMaxError = std::max(result.imageMaxError, relativeError(imageGpu[t + c], expected[c]));
            }
        }
    }
    return result;
}

} // namespace hush::cli
