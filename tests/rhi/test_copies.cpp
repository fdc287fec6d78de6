// Copy commands beyond whole-texture round trips: texture-to-texture regions, buffer
// offsets and row lengths, buffer-to-buffer copies, fills, the queue's buffer
// helpers and mip levels. Expected bytes are composed on the CPU from the inputs.
#include <catch2/catch.hpp>

#include <cstring>

#include "support/gpu_context.hpp"
#include "support/texel_data.hpp"

using namespace hush::rhi;
using namespace hush::test;

TEST_CASE("copies: a texture region copies into another texture at an offset", "[copies][gpu]") {
    ValidationScope validation;
    auto& device = gpu().device;
    auto queue = gpu().queue();
    for (Format f : {Format::R8Unorm, Format::RGBA16Float, Format::RGBA32Float}) {
        INFO(toString(f));
        const uint32_t bpp = formatInfo(f).bytesPerPixel;
        const auto usage = TextureUsage::CopySrc | TextureUsage::CopyDst;
        auto a = device.createTexture({.label = "a", .size = {17, 11}, .format = f, .usage = usage});
        auto b = device.createTexture({.label = "b", .size = {13, 9}, .format = f, .usage = usage});
        const auto dataA = edgeTexels(f, 17 * 11, 10);
        auto expectedB = edgeTexels(f, 13 * 9, 11);
        queue.writeTexture({.texture = a, .data = dataA, .after = ResourceState::CopySrc});
        queue.writeTexture({.texture = b, .data = expectedB, .after = ResourceState::CopySrc});
        Readback back;
        submitAndWait([&](CommandEncoder& encoder) {
            encoder.barrier({{b, ResourceState::CopySrc, ResourceState::CopyDst}});
            encoder.copyTextureToTexture({.texture = a, .origin = {2, 1}}, {.texture = b, .origin = {5, 3}}, {6, 4});
            encoder.barrier({{b, ResourceState::CopyDst, ResourceState::CopySrc}});
            back = Readback::ofTexture(encoder, b);
        });
        paste(expectedB, 13, bpp, crop(dataA, 17, bpp, 2, 1, 6, 4), 5, 3, 6, 4);
        CHECK(firstDifference(f, expectedB, back.bytes(), 13) == "");
        CHECK(firstDifference(f, expectedB, queue.readTexture({.texture = b, .state = ResourceState::CopySrc}), 13) ==
              "");
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("copies: buffer offsets and row lengths place texels where they belong", "[copies][gpu]") {
    ValidationScope validation;
    auto& device = gpu().device;
    auto queue = gpu().queue();
    constexpr uint32_t kW = 9, kH = 5, kRowLength = kW + 5;
    constexpr uint64_t kOffset = 256;   // a multiple of every format's texel size
    for (Format f : {Format::R8Unorm, Format::RG16Float, Format::RGBA32Float}) {
        INFO(toString(f));
        const uint32_t bpp = formatInfo(f).bytesPerPixel;
        const uint64_t size = (kOffset + uint64_t(kRowLength) * kH * bpp + 64 + 3) / 4 * 4;   // fillBuffer wants 4-byte sizes
        auto texture = device.createTexture(
            {.label = "rows", .size = {kW, kH}, .format = f, .usage = TextureUsage::CopySrc | TextureUsage::CopyDst});
        const auto data = edgeTexels(f, kW * kH, 12);
        queue.writeTexture({.texture = texture, .data = data, .after = ResourceState::CopySrc});
        auto buffer = device.createBuffer(
            {.label = "rows", .size = size, .usage = BufferUsage::MapRead | BufferUsage::CopyDst});
        submitAndWait([&](CommandEncoder& encoder) {
            encoder.bufferBarrier({{buffer, ResourceState::Undefined, ResourceState::CopyDst}});
            encoder.fillBuffer(buffer, 0xA5A5A5A5u);
            encoder.bufferBarrier({{buffer, ResourceState::CopyDst, ResourceState::CopyDst}});
            encoder.copyTextureToBuffer({.texture = texture},
                                        {.buffer = buffer, .offset = kOffset, .rowLengthTexels = kRowLength});
            encoder.bufferBarrier({{buffer, ResourceState::CopyDst, ResourceState::HostRead}});
        });
        std::vector<std::byte> expected(size, std::byte{0xA5});
        for (uint32_t y = 0; y < kH; ++y)
            std::memcpy(expected.data() + kOffset + uint64_t(y) * kRowLength * bpp, data.data() + size_t(y) * kW * bpp,
                        size_t(kW) * bpp);
        CHECK(buffer.readValues<std::byte>(size) == expected);

        // And back: the padded rows into a sub-rectangle of a second texture.
        auto upload = device.createBuffer(
            {.label = "rows up", .size = size, .usage = BufferUsage::MapWrite | BufferUsage::CopySrc});
        upload.write(expected);
        auto target = device.createTexture({.label = "rows target", .size = {kW + 4, kH + 3}, .format = f,
                                            .usage = TextureUsage::CopySrc | TextureUsage::CopyDst});
        auto targetData = edgeTexels(f, (kW + 4) * (kH + 3), 13);
        queue.writeTexture({.texture = target, .data = targetData, .after = ResourceState::CopyDst});
        Readback back;
        submitAndWait([&](CommandEncoder& encoder) {
            encoder.bufferBarrier({{upload, ResourceState::HostWrite, ResourceState::CopySrc}});
            encoder.copyBufferToTexture({.buffer = upload, .offset = kOffset, .rowLengthTexels = kRowLength},
                                        {.texture = target, .origin = {3, 2}}, {kW, kH});
            encoder.barrier({{target, ResourceState::CopyDst, ResourceState::CopySrc}});
            back = Readback::ofTexture(encoder, target);
        });
        paste(targetData, kW + 4, bpp, data, 3, 2, kW, kH);
        CHECK(firstDifference(f, targetData, back.bytes(), kW + 4) == "");
        CHECK(firstDifference(f, targetData, queue.readTexture({.texture = target, .state = ResourceState::CopySrc}),
                              kW + 4) == "");
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("copies: fillBuffer and copyBufferToBuffer honour offsets and sizes", "[copies][gpu]") {
    ValidationScope validation;
    auto& device = gpu().device;
    constexpr uint64_t kSize = 1024;
    auto a = device.createBuffer({.label = "a", .size = kSize, .usage = BufferUsage::Storage | BufferUsage::CopySrc |
                                                                       BufferUsage::CopyDst});
    auto b = device.createBuffer({.label = "b", .size = kSize, .usage = BufferUsage::Storage | BufferUsage::CopySrc |
                                                                       BufferUsage::CopyDst});
    Readback backA, backB;
    submitAndWait([&](CommandEncoder& encoder) {
        encoder.bufferBarrier({{a, ResourceState::Undefined, ResourceState::CopyDst},
                               {b, ResourceState::Undefined, ResourceState::CopyDst}});
        encoder.fillBuffer(a, 0x11111111u);
        encoder.fillBuffer(b, 0x22222222u);
        encoder.bufferBarrier({{a, ResourceState::CopyDst, ResourceState::CopyDst}});
        encoder.fillBuffer(a, 0x01020304u, 64, 128);   // a[64, 192)
        encoder.bufferBarrier({{a, ResourceState::CopyDst, ResourceState::CopySrc},
                               {b, ResourceState::CopyDst, ResourceState::CopyDst}});
        encoder.copyBufferToBuffer(a, 60, b, 500, 136);   // a[60, 196) -> b[500, 636)
        encoder.bufferBarrier({{b, ResourceState::CopyDst, ResourceState::CopySrc}});
        backA = Readback::ofBuffer(encoder, a, 0, kSize);
        backB = Readback::ofBuffer(encoder, b, 0, kSize);
    });
    const auto gotA = backA.values<uint32_t>();
    const auto gotB = backB.values<uint32_t>();
    CHECK(valuesOf<uint32_t>(readBufferMapped(a, 0, kSize, ResourceState::CopySrc)) == gotA);
    std::vector<uint32_t> expectedA(kSize / 4, 0x11111111u), expectedB(kSize / 4, 0x22222222u);
    for (uint64_t i = 64 / 4; i < 192 / 4; ++i) expectedA[i] = 0x01020304u;
    for (uint64_t i = 0; i < 136 / 4; ++i) expectedB[500 / 4 + i] = expectedA[60 / 4 + i];
    CHECK(gotA == expectedA);
    CHECK(gotB == expectedB);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("copies: queue writeBuffer and readBuffer round trip at an offset", "[copies][gpu]") {
    ValidationScope validation;
    auto buffer = gpu().device.createBuffer(
        {.label = "queue io", .size = 4096, .usage = BufferUsage::Storage | BufferUsage::CopySrc | BufferUsage::CopyDst});
    auto queue = gpu().queue();
    const auto data = edgeTexels(Format::RGBA32Float, 100, 14);   // 1600 bytes, NaN payloads included
    queue.writeBuffer(buffer, 256, data);
    CHECK(queue.readBuffer(buffer, 256, data.size()) == data);
    CHECK(queue.readBuffer(buffer, 256 + 16, 32) == std::vector<std::byte>(data.begin() + 16, data.begin() + 48));
    CHECK(queue.readBuffer(buffer).size() == 4096);   // kWholeSize: the whole buffer
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("copies: each mip level writes and reads back on its own", "[copies][gpu]") {
    // Resource states describe the whole texture (TextureBarrier has no mip range), so
    // the first write discards all mips (Undefined) and later ones keep them (CopySrc).
    ValidationScope validation;
    auto queue = gpu().queue();
    auto texture = gpu().device.createTexture({.label = "mips", .size = {16, 8}, .format = Format::RGBA16Float,
                                               .usage = TextureUsage::CopySrc | TextureUsage::CopyDst,
                                               .mipLevelCount = 3});
    const Extent2D extents[] = {{16, 8}, {8, 4}, {4, 2}};
    std::vector<std::vector<std::byte>> data;
    for (uint32_t mip = 0; mip < 3; ++mip) {
        data.push_back(edgeTexels(Format::RGBA16Float, extents[mip].width * extents[mip].height, 20 + mip));
        queue.writeTexture({.texture = texture, .data = data.back(), .mipLevel = mip,
                            .before = mip == 0 ? ResourceState::Undefined : ResourceState::CopySrc,
                            .after = ResourceState::CopySrc});
    }
    for (uint32_t mip = 0; mip < 3; ++mip) {
        INFO("mip " << mip);
        const auto got = queue.readTexture({.texture = texture, .mipLevel = mip, .state = ResourceState::CopySrc});
        CHECK(firstDifference(Format::RGBA16Float, data[mip], got, extents[mip].width) == "");
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
