// Explicit barriers: hazards that synchronization validation would report, and
// results that would be wrong, if the before/after states were not honoured. The
// RHI tracks no state, so every transition here is written out.
#include <catch2/catch.hpp>

#include <algorithm>

#include "support/gpu_context.hpp"
#include "support/half.hpp"

using namespace hush::rhi;
using namespace hush::test;

TEST_CASE("barriers: isReadOnly classifies resource states", "[barriers]") {
    for (auto s : {ResourceState::CopySrc, ResourceState::SampledRead, ResourceState::StorageRead,
                   ResourceState::UniformRead, ResourceState::HostRead}) {
        INFO(toString(s));
        CHECK(isReadOnly(s));
    }
    for (auto s : {ResourceState::CopyDst, ResourceState::StorageWrite, ResourceState::StorageReadWrite,
                   ResourceState::HostWrite, ResourceState::General}) {
        INFO(toString(s));
        CHECK_FALSE(isReadOnly(s));
    }
}

TEST_CASE("barriers: read-modify-write dispatches separated by barriers accumulate", "[barriers][gpu]") {
    // barriers/add_index.comp: values[i] += i + 1, eight times. Exact (integers).
    ValidationScope validation;
    auto& device = gpu().device;
    constexpr uint32_t kCount = 1000, kCapacity = 1024, kRounds = 8;
    auto pipeline = computePipeline("barriers/add_index");
    auto values = device.createBuffer({.label = "values", .size = kCapacity * 4,
                                       .usage = BufferUsage::Storage | BufferUsage::CopyDst | BufferUsage::CopySrc});
    auto group = device.createBindGroup(
        {.label = "values", .layout = pipeline.getBindGroupLayout(0), .entries = {{.binding = 0, .buffer = values}}});
    Readback back;
    submitAndWait([&](CommandEncoder& encoder) {
        encoder.bufferBarrier({{values, ResourceState::Undefined, ResourceState::CopyDst}});
        encoder.fillBuffer(values, 0);
        ResourceState state = ResourceState::CopyDst;
        for (uint32_t round = 0; round < kRounds; ++round) {
            encoder.bufferBarrier({{values, state, ResourceState::StorageReadWrite}});
            state = ResourceState::StorageReadWrite;
            auto pass = encoder.beginComputePass({.label = "add"});
            pass.setPipeline(pipeline);
            pass.setBindGroup(0, group);
            pass.setParams(kCount);
            pass.dispatchThreads(kCount);
            pass.end();
        }
        encoder.bufferBarrier({{values, state, ResourceState::CopySrc}});
        back = Readback::ofBuffer(encoder, values, 0, kCapacity * 4);
    });
    const auto got = back.values<uint32_t>();
    std::vector<uint32_t> expected(kCapacity, 0);
    for (uint32_t i = 0; i < kCount; ++i) expected[i] = kRounds * (i + 1);
    CHECK(got == expected);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("barriers: a texture moves between storage write and sampled read and copy", "[barriers][gpu]") {
    // barriers/write_pattern.comp writes A = (x, y, z, w); barriers/fetch_transform.comp
    // reads A as a sampled texture and writes B = 2A + 1. Twice, so that A is written
    // again after being read (write-after-read) and B after being copied. Small
    // integers: exact in fp16.
    ValidationScope validation;
    auto& device = gpu().device;
    auto queue = gpu().queue();
    constexpr uint32_t kW = 20, kH = 12;
    const auto usage = TextureUsage::StorageBinding | TextureUsage::TextureBinding | TextureUsage::CopySrc;
    auto a = device.createTexture({.label = "a", .size = {kW, kH}, .format = Format::RGBA16Float, .usage = usage});
    auto b = device.createTexture({.label = "b", .size = {kW, kH}, .format = Format::RGBA16Float, .usage = usage});
    auto write = computePipeline("barriers/write_pattern");
    auto transform = computePipeline("barriers/fetch_transform");
    auto writeGroup = device.createBindGroup(
        {.label = "write a", .layout = write.getBindGroupLayout(0), .entries = {{.name = "dst", .texture = a}}});
    auto transformGroup = device.createBindGroup({.label = "a to b",
                                                  .layout = transform.getBindGroupLayout(0),
                                                  .entries = {{.name = "src", .texture = a}, {.name = "dst", .texture = b}}});

    auto expectedB = [&](float z, float w) {
        std::vector<uint16_t> out;
        for (uint32_t y = 0; y < kH; ++y)
            for (uint32_t x = 0; x < kW; ++x)
                for (float v : {float(x), float(y), z, w}) out.push_back(floatToHalf(2.0f * v + 1.0f));
        return out;
    };
    auto record = [&](CommandEncoder& encoder, float z, float w, bool first) -> Readback {
        encoder.barrier({{a, first ? ResourceState::Undefined : ResourceState::SampledRead, ResourceState::StorageWrite},
                         {b, first ? ResourceState::Undefined : ResourceState::CopySrc, ResourceState::StorageWrite}});
        auto pass = encoder.beginComputePass({.label = "write a"});
        pass.setPipeline(write);
        pass.setBindGroup(0, writeGroup);
        const float base[4] = {0.0f, 0.0f, z, w};
        pass.setPushConstants(base, sizeof(base));
        pass.dispatchThreads(kW, kH);
        pass.end();
        encoder.barrier({{a, ResourceState::StorageWrite, ResourceState::SampledRead}});
        auto pass2 = encoder.beginComputePass({.label = "a to b"});
        pass2.setPipeline(transform);
        pass2.setBindGroup(0, transformGroup);
        pass2.dispatchThreads(kW, kH);
        pass2.end();
        encoder.barrier({{b, ResourceState::StorageWrite, ResourceState::CopySrc}});
        return Readback::ofTexture(encoder, b);
    };

    Readback first, second, third;
    submitAndWait([&](CommandEncoder& encoder) { first = record(encoder, 3.0f, -1.0f, true); });
    CHECK(first.values<uint16_t>() == expectedB(3.0f, -1.0f));
    CHECK(valuesOf<uint16_t>(queue.readTexture({.texture = b, .state = ResourceState::CopySrc})) == expectedB(3.0f, -1.0f));
    // Two rounds in one command buffer: the second must not overtake the first's reads.
    submitAndWait([&](CommandEncoder& encoder) {
        second = record(encoder, 5.0f, 0.5f, false);
        third = record(encoder, 7.0f, 2.0f, false);
    });
    CHECK(second.values<uint16_t>() == expectedB(5.0f, 0.5f));
    CHECK(third.values<uint16_t>() == expectedB(7.0f, 2.0f));
    // A itself, read in its sampled state.
    const auto gotA = valuesOf<uint16_t>(queue.readTexture({.texture = a, .state = ResourceState::SampledRead}));
    REQUIRE(gotA.size() == size_t(kW) * kH * 4);
    CHECK(halfToFloat(gotA[(5 * kW + 9) * 4 + 0]) == 9.0f);
    CHECK(halfToFloat(gotA[(5 * kW + 9) * 4 + 1]) == 5.0f);
    CHECK(halfToFloat(gotA[(5 * kW + 9) * 4 + 2]) == 7.0f);
    CHECK(halfToFloat(gotA[(5 * kW + 9) * 4 + 3]) == 2.0f);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("barriers: each mip level is written through its own view", "[barriers][gpu]") {
    // barriers/write_pattern.comp through createView(mip): texel (x, y) of mip m becomes
    // (x, y, m, 7). imageSize() in the shader is the view's mip size.
    ValidationScope validation;
    auto& device = gpu().device;
    auto queue = gpu().queue();
    auto texture = device.createTexture({.label = "mips", .size = {16, 12}, .format = Format::RGBA16Float,
                                         .usage = TextureUsage::StorageBinding | TextureUsage::CopySrc,
                                         .mipLevelCount = 3});
    auto write = computePipeline("barriers/write_pattern");
    const Extent2D extents[] = {{16, 12}, {8, 6}, {4, 3}};
    std::vector<BindGroup> groups;
    for (uint32_t mip = 0; mip < 3; ++mip) {
        auto view = texture.createView(mip);
        CHECK(view.baseMipLevel() == mip);
        CHECK(view.mipLevelCount() == 1);
        CHECK(view.texture() == texture);
        groups.push_back(device.createBindGroup({.label = "mip",
                                                 .layout = write.getBindGroupLayout(0),
                                                 .entries = {{.name = "dst", .textureView = view}}}));
    }
    std::vector<Readback> backs(3);
    submitAndWait([&](CommandEncoder& encoder) {
        encoder.barrier({{texture, ResourceState::Undefined, ResourceState::StorageWrite}});
        auto pass = encoder.beginComputePass({.label = "mips"});
        pass.setPipeline(write);
        for (uint32_t mip = 0; mip < 3; ++mip) {
            pass.setBindGroup(0, groups[mip]);
            const float base[4] = {0.0f, 0.0f, float(mip), 7.0f};
            pass.setPushConstants(base, sizeof(base));
            pass.dispatchThreads(extents[mip].width, extents[mip].height);
        }
        pass.end();
        encoder.barrier({{texture, ResourceState::StorageWrite, ResourceState::CopySrc}});
        for (uint32_t mip = 0; mip < 3; ++mip) backs[mip] = Readback::ofTexture(encoder, texture, mip);
    });
    for (uint32_t mip = 0; mip < 3; ++mip) {
        INFO("mip " << mip);
        std::vector<uint16_t> expected;
        for (uint32_t y = 0; y < extents[mip].height; ++y)
            for (uint32_t x = 0; x < extents[mip].width; ++x)
                for (float v : {float(x), float(y), float(mip), 7.0f}) expected.push_back(floatToHalf(v));
        CHECK(backs[mip].values<uint16_t>() == expected);
        CHECK(valuesOf<uint16_t>(queue.readTexture({.texture = texture, .mipLevel = mip, .state = ResourceState::CopySrc})) ==
              expected);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
