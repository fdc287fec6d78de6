// Explicit layouts: one BindGroupLayout written by hand, used by two pipelines whose
// shaders each use part of it, and one bind group shared by both.
#include <catch2/catch.hpp>

#include <cmath>

#include "support/gpu_context.hpp"

using namespace hush::rhi;
using namespace hush::test;

namespace {

BindGroupLayout sharedLayout() {
    return gpu().device.createBindGroupLayout({
        .label = "shared",
        .entries = {{.binding = 0, .kind = BindingKind::StorageTexture, .name = "src",
                     .storageFormat = Format::RGBA32Float, .access = StorageAccess::ReadOnly},
                    {.binding = 1, .kind = BindingKind::StorageTexture, .name = "dst",
                     .storageFormat = Format::RGBA32Float, .access = StorageAccess::WriteOnly},
                    {.binding = 2, .kind = BindingKind::StorageBuffer, .name = "sums"},
                    {.binding = 3, .kind = BindingKind::UniformBuffer, .name = "params"}},
    });
}

bool close(float got, double want, double rel) { return std::abs(double(got) - want) <= rel * std::max(1.0, std::abs(want)); }

} // namespace

TEST_CASE("layouts: an explicit layout reports what it was given", "[layouts][gpu]") {
    ValidationScope validation;
    auto layout = sharedLayout();
    CHECK(layout.label() == "shared");
    REQUIRE(layout.entries().size() == 4);
    CHECK(layout.entries()[1].storageFormat == Format::RGBA32Float);
    CHECK(layout.entries()[1].access == StorageAccess::WriteOnly);
    REQUIRE(layout.findName("sums") != nullptr);
    CHECK(layout.findName("sums")->binding == 2);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("layouts: two pipelines share an explicit layout and one bind group", "[layouts][gpu]") {
    // layout/scale.comp:      dst = src * params.scale + push.offset     (bindings 0, 1, 3)
    // layout/accumulate.comp: sums[i] += src.r * push.factor             (bindings 0, 2)
    // Run: scale, accumulate(3), barrier, accumulate(-0.5). Tolerance 1e-6 relative
    // (absolute below 1): one multiply-add per step, fused or not.
    ValidationScope validation;
    auto& device = gpu().device;
    auto queue = gpu().queue();
    constexpr uint32_t kW = 16, kH = 12;

    auto layout = sharedLayout();
    const PipelineLayoutDesc pipelineLayout{.bindGroupLayouts = {layout}, .pushConstantBytes = 16};
    auto scale = computePipeline("layout/scale", "scale", pipelineLayout);
    auto accumulate = computePipeline("layout/accumulate", "accumulate", pipelineLayout);
    CHECK(scale.bindGroupLayoutCount() == 1);
    CHECK(accumulate.bindGroupLayoutCount() == 1);
    CHECK(scale.getBindGroupLayout(0) == layout);
    CHECK(accumulate.getBindGroupLayout(0) == layout);
    CHECK(scale.pushConstantBytes() == 16);
    CHECK(accumulate.pushConstantBytes() == 16);

    std::vector<float> src(kW * kH * 4);
    Lcg rng(21);
    for (float& v : src) v = rng.uniform(-2.0f, 2.0f);
    const float scaleFactors[4] = {2.0f, -1.0f, 0.5f, 3.0f};
    const float offset[4] = {1.0f, 2.0f, 3.0f, 4.0f};

    auto srcTex = device.createTexture({.label = "src", .size = {kW, kH}, .format = Format::RGBA32Float,
                                        .usage = TextureUsage::StorageBinding | TextureUsage::CopyDst});
    auto dstTex = device.createTexture({.label = "dst", .size = {kW, kH}, .format = Format::RGBA32Float,
                                        .usage = TextureUsage::StorageBinding | TextureUsage::CopySrc});
    auto sums = device.createBuffer({.label = "sums", .size = kW * kH * 4,
                                     .usage = BufferUsage::Storage | BufferUsage::CopyDst | BufferUsage::CopySrc});
    auto params = device.createBuffer({.label = "params", .size = 16, .usage = BufferUsage::Uniform | BufferUsage::CopyDst});
    queue.writeTexture({.texture = srcTex, .data = bytesOf(src), .after = ResourceState::StorageRead});
    queue.writeBuffer(params, 0, std::as_bytes(std::span(scaleFactors)));

    auto group = device.createBindGroup({.label = "shared",
                                         .layout = layout,
                                         .entries = {{.name = "src", .texture = srcTex},
                                                     {.name = "dst", .texture = dstTex},
                                                     {.name = "sums", .buffer = sums},
                                                     {.name = "params", .buffer = params}}});
    struct AccumulateParams {
        float factor;
        uint32_t width;
    };
    Readback dstBack, sumsBack;
    submitAndWait([&](CommandEncoder& encoder) {
        encoder.barrier({{dstTex, ResourceState::Undefined, ResourceState::StorageWrite}},
                        {{sums, ResourceState::Undefined, ResourceState::CopyDst}});
        encoder.fillBuffer(sums, 0);
        encoder.barrier({}, {{sums, ResourceState::CopyDst, ResourceState::StorageReadWrite},
                             {params, ResourceState::CopyDst, ResourceState::UniformRead}});
        auto pass = encoder.beginComputePass({.label = "scale then accumulate"});
        pass.setPipeline(scale);
        pass.setBindGroup(0, group);
        pass.setPushConstants(offset, sizeof(offset));
        pass.dispatchThreads(kW, kH);
        pass.setPipeline(accumulate);
        pass.setBindGroup(0, group);
        pass.setParams(AccumulateParams{3.0f, kW});
        pass.dispatchThreads(kW, kH);
        pass.end();
        encoder.bufferBarrier({{sums, ResourceState::StorageReadWrite, ResourceState::StorageReadWrite}});
        auto again = encoder.beginComputePass({.label = "accumulate again"});
        again.setPipeline(accumulate);
        again.setBindGroup(0, group);
        again.setParams(AccumulateParams{-0.5f, kW});
        again.dispatchThreads(kW, kH);
        again.end();
        encoder.barrier({{dstTex, ResourceState::StorageWrite, ResourceState::CopySrc}},
                        {{sums, ResourceState::StorageReadWrite, ResourceState::CopySrc}});
        dstBack = Readback::ofTexture(encoder, dstTex);
        sumsBack = Readback::ofBuffer(encoder, sums, 0, kW * kH * 4);
    });

    const auto dst = dstBack.values<float>();
    const auto got = sumsBack.values<float>();
    REQUIRE(dst.size() == src.size());
    int bad = 0;
    for (uint32_t i = 0; i < kW * kH; ++i) {
        bool ok = true;
        for (int c = 0; c < 4; ++c)
            ok = ok && close(dst[i * 4 + c], double(src[i * 4 + c]) * scaleFactors[c] + offset[c], 1e-6);
        const float r = src[i * 4];
        const float afterFirst = r * 3.0f;   // exact in float up to one rounding
        ok = ok && close(got[i], double(afterFirst) + double(r) * -0.5, 1e-6);
        if (!ok && bad++ < 5) UNSCOPED_INFO("texel " << i << ": dst.r " << dst[i * 4] << ", sum " << got[i]);
    }
    CHECK(bad == 0);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
