// Every format in kAllFormats, through every path a texel can take: queue uploads and
// read-backs, copies to and from buffers, sub-rectangles, and shader storage access.
// Copies must be bit-exact: fp16 max 65504 and subnormals, fp32 NaN payloads and
// +-Inf, R32Uint max and R8 0/255 included (support/texel_data.cpp lists the edges).
#include <catch2/catch.hpp>

#include <string>

#include "support/gpu_context.hpp"
#include "support/texel_data.hpp"

using namespace hush::rhi;
using namespace hush::test;

namespace {

// Odd sizes: rows are not multiples of 4 bytes for R8 and do not fill 8x8 workgroups.
constexpr uint32_t kWidth = 23;
constexpr uint32_t kHeight = 13;   // 299 texels: every R8 value 0..255 appears

constexpr TextureUsage kAllUsages =
    TextureUsage::CopySrc | TextureUsage::CopyDst | TextureUsage::TextureBinding | TextureUsage::StorageBinding;

Texture makeTexture(Format format, TextureUsage usage, const std::string& label) {
    return gpu().device.createTexture({.label = label, .size = {kWidth, kHeight}, .format = format, .usage = usage});
}

} // namespace

TEST_CASE("formats: names sizes and parsing agree", "[formats]") {
    for (Format f : kAllFormats) {
        const auto& info = formatInfo(f);
        INFO(info.name);
        const uint32_t channelBytes = info.channelType == ChannelType::Unorm8    ? 1
                                      : info.channelType == ChannelType::Float16 ? 2
                                                                                  : 4;
        CHECK(info.bytesPerPixel == info.channels * channelBytes);
        CHECK(parseFormat(info.name) == f);
        CHECK(parseFormat(info.glslName) == f);
        CHECK(toString(f) == info.name);
    }
    CHECK(parseFormat("rgba16floatx") == Format::Undefined);
    CHECK(formatInfo(Format::RGBA16Float).bytesPerPixel == 8);
    CHECK(formatInfo(Format::R32Uint).channelType == ChannelType::Uint32);
}

TEST_CASE("formats: the test adapter supports every format for copy sampling and storage", "[formats][gpu]") {
    // The issue asks for all of kAllFormats with storage and sampled usage; lavapipe has them.
    ValidationScope validation;
    for (Format f : kAllFormats) {
        INFO(toString(f));
        CHECK(gpu().adapter.supports(f, kAllUsages));
        auto texture = makeTexture(f, kAllUsages, "all usages");
        CHECK(texture.format() == f);
        CHECK(texture.usage() == kAllUsages);
        CHECK(texture.size() == Extent2D{kWidth, kHeight});
        CHECK(texture.byteSize() == uint64_t(kWidth) * kHeight * formatInfo(f).bytesPerPixel);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("formats: writeTexture then readTexture is bit-exact in every format", "[formats][gpu]") {
    ValidationScope validation;
    auto queue = gpu().queue();
    for (Format f : kAllFormats) {
        INFO(toString(f));
        const auto data = edgeTexels(f, kWidth * kHeight, 1);
        // Sampled-read state (the default) between the two calls.
        auto texture = makeTexture(f, TextureUsage::CopySrc | TextureUsage::CopyDst | TextureUsage::TextureBinding,
                                   "round trip");
        queue.writeTexture({.texture = texture, .data = data});
        CHECK(firstDifference(f, data, queue.readTexture({.texture = texture}), kWidth) == "");
        // And copy-src state.
        auto copyOnly = makeTexture(f, TextureUsage::CopySrc | TextureUsage::CopyDst, "copy only");
        queue.writeTexture({.texture = copyOnly, .data = data, .after = ResourceState::CopySrc});
        CHECK(firstDifference(f, data, queue.readTexture({.texture = copyOnly, .state = ResourceState::CopySrc}),
                              kWidth) == "");
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("formats: copies between textures and buffers are bit-exact in every format", "[formats][gpu]") {
    ValidationScope validation;
    auto& device = gpu().device;
    auto queue = gpu().queue();
    for (Format f : kAllFormats) {
        INFO(toString(f));
        const uint64_t bytes = uint64_t(kWidth) * kHeight * formatInfo(f).bytesPerPixel;

        // Texture -> buffer: upload with writeTexture, copy into a MapRead buffer.
        const auto data = edgeTexels(f, kWidth * kHeight, 2);
        auto texture = makeTexture(f, TextureUsage::CopySrc | TextureUsage::CopyDst, "to buffer");
        queue.writeTexture({.texture = texture, .data = data, .after = ResourceState::CopySrc});
        auto readBack = device.createBuffer(
            {.label = "read back", .size = bytes, .usage = BufferUsage::MapRead | BufferUsage::CopyDst});
        submitAndWait([&](CommandEncoder& encoder) {
            encoder.bufferBarrier({{readBack, ResourceState::Undefined, ResourceState::CopyDst}});
            encoder.copyTextureToBuffer({.texture = texture}, {.buffer = readBack});
            encoder.bufferBarrier({{readBack, ResourceState::CopyDst, ResourceState::HostRead}});
        });
        CHECK(firstDifference(f, data, readBack.readValues<std::byte>(bytes), kWidth) == "");

        // Buffer -> texture: write a MapWrite buffer, copy into a texture, read it back.
        const auto data2 = edgeTexels(f, kWidth * kHeight, 3);
        auto upload = device.createBuffer(
            {.label = "upload", .size = bytes, .usage = BufferUsage::MapWrite | BufferUsage::CopySrc});
        upload.write(data2);
        auto target = makeTexture(f, TextureUsage::CopySrc | TextureUsage::CopyDst, "from buffer");
        Readback back;
        submitAndWait([&](CommandEncoder& encoder) {
            encoder.barrier({{target, ResourceState::Undefined, ResourceState::CopyDst}},
                            {{upload, ResourceState::HostWrite, ResourceState::CopySrc}});
            encoder.copyBufferToTexture({.buffer = upload}, {.texture = target});
            encoder.barrier({{target, ResourceState::CopyDst, ResourceState::CopySrc}});
            back = Readback::ofTexture(encoder, target);
        });
        CHECK(firstDifference(f, data2, back.bytes(), kWidth) == "");
        CHECK(firstDifference(f, data2, queue.readTexture({.texture = target, .state = ResourceState::CopySrc}),
                              kWidth) == "");
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("formats: sub-rectangles write and read back in every format", "[formats][gpu]") {
    ValidationScope validation;
    auto queue = gpu().queue();
    for (Format f : kAllFormats) {
        INFO(toString(f));
        const uint32_t bpp = formatInfo(f).bytesPerPixel;
        auto texture = makeTexture(f, TextureUsage::CopySrc | TextureUsage::CopyDst, "sub-rectangles");
        auto expected = edgeTexels(f, kWidth * kHeight, 4);
        queue.writeTexture({.texture = texture, .data = expected, .after = ResourceState::CopySrc});

        // Overwrite a 5x4 block at (3, 2); the CPU copy gets the same block.
        const auto patch = edgeTexels(f, 5 * 4, 5);
        queue.writeTexture({.texture = texture, .data = patch, .origin = {3, 2}, .size = {5, 4},
                            .before = ResourceState::CopySrc, .after = ResourceState::CopySrc});
        paste(expected, kWidth, bpp, patch, 3, 2, 5, 4);

        CHECK(firstDifference(f, expected, queue.readTexture({.texture = texture, .state = ResourceState::CopySrc}),
                              kWidth) == "");
        // A 7x3 window at (1, 5), overlapping the patch's bottom row.
        const auto window = queue.readTexture(
            {.texture = texture, .origin = {1, 5}, .size = {7, 3}, .state = ResourceState::CopySrc});
        CHECK(firstDifference(f, crop(expected, kWidth, bpp, 1, 5, 7, 3), window, 7) == "");
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("formats: imageLoad and imageStore keep every format's finite values", "[formats][gpu]") {
    // Shader formats/copy_<glsl name> copies src to dst texel by texel. Tolerance: exact,
    // except that float subnormals may come back as zero of the same sign (Vulkan lets
    // shaders and fp16 conversions flush denormals). Unorm8 must survive c/255*255.
    ValidationScope validation;
    auto& device = gpu().device;
    auto queue = gpu().queue();
    for (Format f : kAllFormats) {
        INFO(toString(f));
        auto pipeline = computePipeline("formats/copy_" + std::string(formatInfo(f).glslName));
        REQUIRE(pipeline.getBindGroupLayout(0).findBinding(0) != nullptr);
        CHECK(pipeline.getBindGroupLayout(0).findBinding(0)->storageFormat == f);

        const auto data = finiteTexels(f, kWidth * kHeight, 6);
        auto src = makeTexture(f, TextureUsage::StorageBinding | TextureUsage::CopyDst, "storage src");
        auto dst = makeTexture(f, TextureUsage::StorageBinding | TextureUsage::CopySrc, "storage dst");
        queue.writeTexture({.texture = src, .data = data, .after = ResourceState::StorageRead});
        auto group = device.createBindGroup({.label = "copy",
                                             .layout = pipeline.getBindGroupLayout(0),
                                             .entries = {{.binding = 0, .texture = src}, {.binding = 1, .texture = dst}}});
        Readback back;
        submitAndWait([&](CommandEncoder& encoder) {
            encoder.barrier({{dst, ResourceState::Undefined, ResourceState::StorageWrite}});
            auto pass = encoder.beginComputePass({.label = "copy"});
            pass.setPipeline(pipeline);
            pass.setBindGroup(0, group);
            pass.dispatchThreads(kWidth, kHeight);
            pass.end();
            encoder.barrier({{dst, ResourceState::StorageWrite, ResourceState::CopySrc}});
            back = Readback::ofTexture(encoder, dst);
        });
        CHECK(firstDifference(f, data, back.bytes(), kWidth, /*allowFlush=*/true) == "");
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
