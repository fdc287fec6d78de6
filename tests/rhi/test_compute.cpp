// Compute shaders against CPU computations of the same functions. Tolerances are
// stated per test; inputs are pseudo-random but fixed (seeded).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

#include "support/gpu_context.hpp"
#include "support/half.hpp"

using namespace hush::rhi;
using namespace hush::test;
using hush::Error;
using hush::ErrorKind;

namespace {

// |got - want| <= rel * max(1, |want|)
bool close(float got, double want, double rel) { return std::abs(double(got) - want) <= rel * std::max(1.0, std::abs(want)); }

} // namespace

TEST_CASE("compute: a per-pixel function over an RGBA32F storage texture matches the CPU", "[compute][gpu]") {
    // Shader compute/pixel_function.comp. Tolerance 1e-5 relative (absolute below 1):
    // a handful of float roundings (GPUs may fuse a*b+c) and GLSL's sqrt (3 ULP).
    ValidationScope validation;
    auto& device = gpu().device;
    auto queue = gpu().queue();
    constexpr uint32_t kW = 67, kH = 45;   // odd: the shader's bounds check matters

    struct Params {
        float scale[4];
        float bias[4];
        uint32_t size[2];
    } params = {{1.5f, -0.5f, 2.0f, 1.0f}, {0.25f, 1.0f, -3.0f, 0.125f}, {kW, kH}};
    static_assert(sizeof(Params) == 40);

    std::vector<float> src(size_t(kW) * kH * 4);
    Lcg rng(7);
    for (float& v : src) v = rng.uniform(-4.0f, 4.0f);

    auto pipeline = computePipeline("compute/pixel_function", "pixel function");
    CHECK(pipeline.pushConstantBytes() == sizeof(Params));
    CHECK(pipeline.workgroupSize() == std::array<uint32_t, 3>{8, 8, 1});

    auto srcTex = device.createTexture({.label = "src", .size = {kW, kH}, .format = Format::RGBA32Float,
                                        .usage = TextureUsage::StorageBinding | TextureUsage::CopyDst});
    auto dstTex = device.createTexture({.label = "dst", .size = {kW, kH}, .format = Format::RGBA32Float,
                                        .usage = TextureUsage::StorageBinding | TextureUsage::CopySrc});
    auto luminance = device.createBuffer(
        {.label = "luminance", .size = uint64_t(kW) * kH * 4, .usage = BufferUsage::Storage | BufferUsage::CopySrc});
    queue.writeTexture({.texture = srcTex, .data = bytesOf(src), .after = ResourceState::StorageRead});

    auto group = device.createBindGroup({.label = "pixel function",
                                         .layout = pipeline.getBindGroupLayout(0),
                                         .entries = {{.name = "srcImage", .texture = srcTex},
                                                     {.name = "dstImage", .texture = dstTex},
                                                     {.binding = 2, .buffer = luminance}}});
    Readback dstBack, lumBack;
    submitAndWait([&](CommandEncoder& encoder) {
        encoder.barrier({{dstTex, ResourceState::Undefined, ResourceState::StorageWrite}},
                        {{luminance, ResourceState::Undefined, ResourceState::StorageWrite}});
        auto pass = encoder.beginComputePass({.label = "pixel function"});
        pass.setPipeline(pipeline);
        pass.setBindGroup(0, group);
        pass.setParams(params);
        pass.dispatchThreads(kW, kH);
        pass.end();
        encoder.barrier({{dstTex, ResourceState::StorageWrite, ResourceState::CopySrc}},
                        {{luminance, ResourceState::StorageWrite, ResourceState::CopySrc}});
        dstBack = Readback::ofTexture(encoder, dstTex);
        lumBack = Readback::ofBuffer(encoder, luminance, 0, uint64_t(kW) * kH * 4);
    });

    const auto dst = dstBack.values<float>();
    const auto lum = lumBack.values<float>();
    // The queue's own read-back says the same.
    CHECK(valuesOf<float>(queue.readTexture({.texture = dstTex, .state = ResourceState::CopySrc})) == dst);
    REQUIRE(dst.size() == src.size());
    REQUIRE(lum.size() == size_t(kW) * kH);
    int bad = 0;
    for (uint32_t y = 0; y < kH; ++y) {
        for (uint32_t x = 0; x < kW; ++x) {
            const size_t i = size_t(y) * kW + x;
            const float* c = &src[i * 4];
            double want[4];
            for (int k = 0; k < 3; ++k) want[k] = double(c[k]) * params.scale[k] + params.bias[k];
            want[3] = std::sqrt(std::abs(double(c[3]))) + params.bias[3];
            const double wantLum = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2] + double(x) - 0.5 * double(y);
            bool ok = close(lum[i], wantLum, 1e-5);
            for (int k = 0; k < 4; ++k) ok = ok && close(dst[i * 4 + k], want[k], 1e-5);
            if (!ok && bad++ < 5) {
                UNSCOPED_INFO("pixel (" << x << ", " << y << "): got (" << dst[i * 4] << ", " << dst[i * 4 + 1] << ", "
                                        << dst[i * 4 + 2] << ", " << dst[i * 4 + 3] << ") lum " << lum[i]
                                        << ", want (" << want[0] << ", " << want[1] << ", " << want[2] << ", "
                                        << want[3] << ") lum " << wantLum);
            }
        }
    }
    CHECK(bad == 0);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("compute: uniform-buffer parameters and a read-only storage input match the CPU", "[compute][gpu]") {
    // Shader compute/saxpy_uniform.comp: y[i] = a * x[i] + b for i < count. Tolerance
    // 2^-20 relative (absolute below 1): one multiply-add, fused or not. Elements past
    // `count` must keep the fill pattern.
    ValidationScope validation;
    auto& device = gpu().device;
    auto queue = gpu().queue();
    constexpr uint32_t kCount = 1000, kCapacity = 1024;   // 1000: not a multiple of the 64-wide workgroup
    struct Params {
        float a, b;
        uint32_t count, pad;
    } params = {0.75f, -3.5f, kCount, 0};

    std::vector<float> x(kCount);
    Lcg rng(11);
    for (float& v : x) v = rng.uniform(-100.0f, 100.0f);

    auto pipeline = computePipeline("compute/saxpy_uniform", "saxpy");
    auto uniforms = device.createBuffer(
        {.label = "params", .size = sizeof(Params), .usage = BufferUsage::Uniform | BufferUsage::CopyDst});
    auto upload = device.createBuffer(
        {.label = "x upload", .size = kCount * 4, .usage = BufferUsage::MapWrite | BufferUsage::CopySrc});
    auto xs = device.createBuffer({.label = "x", .size = kCount * 4, .usage = BufferUsage::Storage | BufferUsage::CopyDst});
    auto ys = device.createBuffer(
        {.label = "y", .size = kCapacity * 4, .usage = BufferUsage::Storage | BufferUsage::CopyDst | BufferUsage::CopySrc});
    queue.writeBuffer(uniforms, 0, std::as_bytes(std::span(&params, 1)));
    upload.writeValues(std::span<const float>(x));

    auto group = device.createBindGroup({.label = "saxpy",
                                         .layout = pipeline.getBindGroupLayout(0),
                                         .entries = {{.binding = 0, .buffer = uniforms},
                                                     {.binding = 1, .buffer = xs},
                                                     {.binding = 2, .buffer = ys}}});
    Readback yBack;
    submitAndWait([&](CommandEncoder& encoder) {
        encoder.bufferBarrier({{upload, ResourceState::HostWrite, ResourceState::CopySrc},
                               {xs, ResourceState::Undefined, ResourceState::CopyDst},
                               {ys, ResourceState::Undefined, ResourceState::CopyDst}});
        encoder.copyBufferToBuffer(upload, 0, xs, 0, kCount * 4);
        encoder.fillBuffer(ys, 0xDEADBEEFu);
        encoder.bufferBarrier({{uniforms, ResourceState::CopyDst, ResourceState::UniformRead},
                               {xs, ResourceState::CopyDst, ResourceState::StorageRead},
                               {ys, ResourceState::CopyDst, ResourceState::StorageWrite}});
        auto pass = encoder.beginComputePass({.label = "saxpy"});
        pass.setPipeline(pipeline);
        pass.setBindGroup(0, group);
        pass.dispatchWorkgroups((kCount + 63) / 64);
        pass.end();
        encoder.bufferBarrier({{ys, ResourceState::StorageWrite, ResourceState::CopySrc}});
        yBack = Readback::ofBuffer(encoder, ys, 0, kCapacity * 4);
    });
    const auto bytes = yBack.bytes();
    const auto y = valuesOf<float>(bytes);
    const auto raw = valuesOf<uint32_t>(bytes);
    int bad = 0;
    for (uint32_t i = 0; i < kCount; ++i) {
        const double want = double(params.a) * x[i] + params.b;
        if (!close(y[i], want, std::ldexp(1.0, -20)) && bad++ < 5)
            UNSCOPED_INFO("y[" << i << "] = " << y[i] << ", want " << want);
    }
    CHECK(bad == 0);
    for (uint32_t i = kCount; i < kCapacity; ++i) CHECK(raw[i] == 0xDEADBEEFu);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("compute: separate and combined samplers return the texels the CPU expects", "[compute][gpu]") {
    // Shader compute/sampling.comp on an 8x4 RGBA16F texture of multiples of 1/4 (exact
    // in fp16). Nearest sampling and texelFetch: exact. Linear sampling halfway between
    // texels (weights exactly 1/2 and 1/4 with power-of-two sizes): 1e-3 relative,
    // since Vulkan does not pin down filtering arithmetic.
    ValidationScope validation;
    auto& device = gpu().device;
    constexpr uint32_t kW = 8, kH = 4;
    std::vector<uint16_t> texels(kW * kH * 4);
    Lcg rng(5);
    for (auto& t : texels) t = floatToHalf(float(rng.next() % 64) * 0.25f);
    auto texel = [&](uint32_t x, uint32_t y, int c) {
        return double(halfToFloat(texels[(std::min(y, kH - 1) * kW + std::min(x, kW - 1)) * 4 + c]));
    };

    auto texture = device.createTexture({.label = "sampled", .size = {kW, kH}, .format = Format::RGBA16Float,
                                         .usage = TextureUsage::TextureBinding | TextureUsage::CopyDst});
    gpu().queue().writeTexture({.texture = texture, .data = bytesOf(texels)});   // -> SampledRead
    auto nearest = device.createSampler({.label = "nearest", .magFilter = FilterMode::Nearest,
                                         .minFilter = FilterMode::Nearest});
    auto linear = device.createSampler({.label = "linear"});
    const uint64_t outBytes = uint64_t(kW) * kH * 4 * 16;
    auto out = device.createBuffer({.label = "samples", .size = outBytes, .usage = BufferUsage::Storage | BufferUsage::CopySrc});

    auto pipeline = computePipeline("compute/sampling", "sampling");
    auto group = device.createBindGroup({.label = "sampling",
                                         .layout = pipeline.getBindGroupLayout(0),
                                         .entries = {{.name = "tex", .texture = texture},
                                                     {.name = "nearestSampler", .sampler = nearest},
                                                     {.name = "combinedLinear", .texture = texture, .sampler = linear},
                                                     {.name = "Samples", .buffer = out}}});
    Readback back;
    submitAndWait([&](CommandEncoder& encoder) {
        encoder.bufferBarrier({{out, ResourceState::Undefined, ResourceState::StorageWrite}});
        auto pass = encoder.beginComputePass();
        pass.setPipeline(pipeline);
        pass.setBindGroup(0, group);
        pass.dispatchThreads(kW, kH);
        pass.end();
        encoder.bufferBarrier({{out, ResourceState::StorageWrite, ResourceState::CopySrc}});
        back = Readback::ofBuffer(encoder, out, 0, outBytes);
    });
    const auto got = back.values<float>();
    int bad = 0;
    for (uint32_t y = 0; y < kH; ++y) {
        for (uint32_t x = 0; x < kW; ++x) {
            for (int c = 0; c < 4; ++c) {
                const float* s = &got[((y * kW + x) * 4) * 4];
                const double exact = texel(x, y, c);
                const double right = (texel(x, y, c) + texel(x + 1, y, c)) / 2;
                const double corner = (texel(x, y, c) + texel(x + 1, y, c) + texel(x, y + 1, c) + texel(x + 1, y + 1, c)) / 4;
                const bool ok = s[0 * 4 + c] == exact && close(s[1 * 4 + c], right, 1e-3) && s[2 * 4 + c] == exact &&
                                close(s[3 * 4 + c], corner, 1e-3);
                if (!ok && bad++ < 5)
                    UNSCOPED_INFO("texel (" << x << ", " << y << ") channel " << c << ": nearest " << s[c] << ", linear "
                                            << s[4 + c] << ", fetch " << s[8 + c] << ", corner " << s[12 + c]
                                            << "; want " << exact << ", " << right << ", " << exact << ", " << corner);
            }
        }
    }
    CHECK(bad == 0);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("compute: dispatchThreads covers an odd-sized grid exactly", "[compute][gpu]") {
    // Shader compute/coverage.comp (8x4 workgroups) writes 1 + x + w*y into each cell;
    // 64 cells past the grid must keep their fill value.
    ValidationScope validation;
    auto& device = gpu().device;
    constexpr uint32_t kW = 67, kH = 45, kTail = 64;
    const uint64_t bytes = (uint64_t(kW) * kH + kTail) * 4;
    auto pipeline = computePipeline("compute/coverage");
    CHECK(pipeline.workgroupSize() == std::array<uint32_t, 3>{8, 4, 1});
    auto cells = device.createBuffer(
        {.label = "cells", .size = bytes, .usage = BufferUsage::Storage | BufferUsage::CopySrc | BufferUsage::CopyDst});
    auto group = device.createBindGroup(
        {.label = "coverage", .layout = pipeline.getBindGroupLayout(0), .entries = {{.name = "Cells", .buffer = cells}}});
    const uint32_t params[2] = {kW, kH};
    Readback back;
    submitAndWait([&](CommandEncoder& encoder) {
        encoder.bufferBarrier({{cells, ResourceState::Undefined, ResourceState::CopyDst}});
        encoder.fillBuffer(cells, 0xFFFFFFFFu);
        encoder.bufferBarrier({{cells, ResourceState::CopyDst, ResourceState::StorageWrite}});
        auto pass = encoder.beginComputePass({.label = "coverage"});
        pass.setPipeline(pipeline);
        pass.setBindGroup(0, group);
        pass.setPushConstants(params, sizeof(params));
        pass.dispatchThreads(kW, kH);
        pass.end();
        encoder.bufferBarrier({{cells, ResourceState::StorageWrite, ResourceState::CopySrc}});
        back = Readback::ofBuffer(encoder, cells, 0, bytes);
    });
    const auto got = back.values<uint32_t>();
    std::vector<uint32_t> expected(size_t(kW) * kH + kTail, 0xFFFFFFFFu);
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) expected[size_t(y) * kW + x] = 1 + x + kW * y;
    CHECK(got == expected);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("compute: submissions are numbered in order and complete in order", "[compute][gpu]") {
    ValidationScope validation;
    auto& device = gpu().device;
    auto queue = gpu().queue();
    auto buffer = device.createBuffer({.label = "order", .size = 256, .usage = BufferUsage::CopyDst | BufferUsage::CopySrc});
    auto record = [&](uint32_t value, ResourceState before) {
        auto encoder = device.createCommandEncoder({.label = "fill"});
        encoder.bufferBarrier({{buffer, before, ResourceState::CopyDst}});
        encoder.fillBuffer(buffer, value);
        encoder.bufferBarrier({{buffer, ResourceState::CopyDst, ResourceState::CopySrc}});
        return encoder.finish();
    };
    const SubmissionId first = queue.submit(record(1, ResourceState::Undefined));
    const CommandBuffer pair[] = {record(2, ResourceState::CopySrc), record(3, ResourceState::CopySrc)};
    const SubmissionId second = queue.submit(pair);
    CHECK(second > first);
    CHECK(queue.lastSubmitted() == second);
    queue.wait(second);
    CHECK(queue.isComplete(first));
    CHECK(queue.isComplete(second));
    // The last fill in submission order wins.
    const auto values = valuesOf<uint32_t>(readBufferMapped(buffer, 0, 256, ResourceState::CopySrc));
    CHECK(std::all_of(values.begin(), values.end(), [](uint32_t v) { return v == 3; }));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("compute: an indirect dispatch runs the workgroup counts its buffer holds, and needs Indirect usage",
          "[compute][gpu]") {
    // compute/coverage.comp (8x4 workgroups) over a 67x45 grid, dispatched with counts
    // (3, 5, 1) read from a buffer: exactly the top-left 24x20 cells are written.
    ValidationScope validation;
    auto& device = gpu().device;
    constexpr uint32_t kW = 67, kH = 45;
    const uint64_t bytes = uint64_t(kW) * kH * 4;
    auto pipeline = computePipeline("compute/coverage");
    auto cells = device.createBuffer(
        {.label = "cells", .size = bytes, .usage = BufferUsage::Storage | BufferUsage::CopySrc | BufferUsage::CopyDst});
    auto counts = device.createBuffer({.label = "counts", .size = 16, .usage = BufferUsage::Indirect | BufferUsage::CopyDst});
    auto notIndirect = device.createBuffer({.label = "plain", .size = 16, .usage = BufferUsage::Storage});
    const uint32_t groups[4] = {3, 5, 1, 0};
    gpu().queue().writeBuffer(counts, 0, std::as_bytes(std::span(groups)));
    auto group = device.createBindGroup(
        {.label = "coverage", .layout = pipeline.getBindGroupLayout(0), .entries = {{.name = "Cells", .buffer = cells}}});
    const uint32_t params[2] = {kW, kH};
    std::optional<Error> refused, offsetRefused;
    Readback back;
    submitAndWait([&](CommandEncoder& encoder) {
        encoder.bufferBarrier({{cells, ResourceState::Undefined, ResourceState::CopyDst},
                               {counts, ResourceState::CopyDst, ResourceState::IndirectRead}});
        encoder.fillBuffer(cells, 0xFFFFFFFFu);
        encoder.bufferBarrier({{cells, ResourceState::CopyDst, ResourceState::StorageWrite}});
        auto pass = encoder.beginComputePass({.label = "coverage"});
        pass.setPipeline(pipeline);
        pass.setBindGroup(0, group);
        pass.setPushConstants(params, sizeof(params));
        refused = errorFrom([&] { pass.dispatchWorkgroupsIndirect(notIndirect); });
        offsetRefused = errorFrom([&] { pass.dispatchWorkgroupsIndirect(counts, 8); });
        pass.dispatchWorkgroupsIndirect(counts);
        pass.end();
        encoder.bufferBarrier({{cells, ResourceState::StorageWrite, ResourceState::CopySrc}});
        back = Readback::ofBuffer(encoder, cells, 0, bytes);
    });
    const auto got = back.values<uint32_t>();
    std::vector<uint32_t> expected(size_t(kW) * kH, 0xFFFFFFFFu);
    for (uint32_t y = 0; y < 20; ++y)
        for (uint32_t x = 0; x < 24; ++x) expected[size_t(y) * kW + x] = 1 + x + kW * y;
    CHECK(got == expected);
    REQUIRE(refused);
    CHECK(refused->kind() == ErrorKind::InvalidArgument);
    CHECK_THAT(refused->what(), Catch::Contains("'plain'") && Catch::Contains("BufferUsage::Indirect"));
    REQUIRE(offsetRefused);
    CHECK_THAT(offsetRefused->what(), Catch::Contains("offset 8") && Catch::Contains("'counts'"));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
