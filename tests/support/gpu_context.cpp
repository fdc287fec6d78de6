#include "support/gpu_context.hpp"

#include <algorithm>
#include <iostream>
#include <memory>
#include <mutex>

#include <hush_test_shaders.hpp>

namespace hush::test {

namespace {

struct MessageLog {
    std::mutex mutex;
    std::vector<std::string> messages;
};

// Never destroyed: validation callbacks may fire while statics are torn down.
MessageLog& log() {
    static auto* instance = new MessageLog;
    return *instance;
}

std::unique_ptr<GpuContext>& context() {
    static std::unique_ptr<GpuContext> instance;
    return instance;
}

} // namespace

void recordValidationMessage(const std::string& message) {
    {
        std::lock_guard lock(log().mutex);
        log().messages.push_back(message);
    }
    std::cerr << "VALIDATION: " << message << '\n';
}

size_t validationMessageCount() {
    std::lock_guard lock(log().mutex);
    return log().messages.size();
}

std::vector<std::string> validationMessagesSince(size_t first) {
    std::lock_guard lock(log().mutex);
    if (first >= log().messages.size()) return {};
    return {log().messages.begin() + std::ptrdiff_t(first), log().messages.end()};
}

std::string joinMessages(const std::vector<std::string>& messages) {
    std::string out;
    for (const auto& m : messages) out += "  " + m + "\n";
    return out.empty() ? "  (none)\n" : out;
}

GpuContext& gpu() {
    auto& ctx = context();
    if (!ctx) {
        auto created = std::make_unique<GpuContext>();
        created->instance = rhi::Instance::create({
            .applicationName = "hush_rhi_tests",
            .validation = true,
            .validationFromEnvironment = false,
            .onValidationMessage = [](const std::string& message) { recordValidationMessage(message); },
        });
        created->adapter = created->instance.requestAdapter();
        created->device = created->adapter.createDevice({.label = "hush_rhi_tests"});
        ctx = std::move(created);
    }
    return *ctx;
}


void releaseGpu() {
    auto& ctx = context();
    if (!ctx) return;
    ctx->device.waitIdle();
    ctx.reset();
}

rhi::ShaderModule shaderModule(std::string_view name) {
    return gpu().device.createShaderModule({.label = std::string(name), .code = test_shaders::find(name)});
}

rhi::ComputePipeline computePipeline(std::string_view name, const std::string& label,
                                     std::optional<rhi::PipelineLayoutDesc> layout) {
    return gpu().device.createComputePipeline({
        .label = label.empty() ? std::string(name) : label,
        .module = shaderModule(name),
        .layout = std::move(layout),
    });
}

std::vector<std::byte> readBufferMapped(const rhi::Buffer& buffer, uint64_t offset, uint64_t size,
                                        rhi::ResourceState state) {
    using rhi::ResourceState;
    auto staging = gpu().device.createBuffer(
        {.label = "read-back staging", .size = size, .usage = rhi::BufferUsage::MapRead | rhi::BufferUsage::CopyDst});
    submitAndWait(
        [&](rhi::CommandEncoder& encoder) {
            encoder.barrier({}, {{buffer, state, ResourceState::CopySrc},
                                 {staging, ResourceState::Undefined, ResourceState::CopyDst}});
            encoder.copyBufferToBuffer(buffer, offset, staging, 0, size);
            encoder.barrier({}, {{buffer, ResourceState::CopySrc, state},
                                 {staging, ResourceState::CopyDst, ResourceState::HostRead}});
        },
        "read-back");
    std::vector<std::byte> out(size);
    staging.read(out);
    return out;
}

namespace {
rhi::Buffer recordStaging(rhi::CommandEncoder& encoder, uint64_t size) {
    auto staging = gpu().device.createBuffer(
        {.label = "readback", .size = size, .usage = rhi::BufferUsage::MapRead | rhi::BufferUsage::CopyDst});
    encoder.bufferBarrier({{staging, rhi::ResourceState::Undefined, rhi::ResourceState::CopyDst}});
    return staging;
}
} // namespace

Readback Readback::ofBuffer(rhi::CommandEncoder& encoder, const rhi::Buffer& buffer, uint64_t offset, uint64_t size) {
    Readback out;
    out.size_ = size;
    out.staging_ = recordStaging(encoder, size);
    encoder.copyBufferToBuffer(buffer, offset, out.staging_, 0, size);
    encoder.bufferBarrier({{out.staging_, rhi::ResourceState::CopyDst, rhi::ResourceState::HostRead}});
    return out;
}

Readback Readback::ofTexture(rhi::CommandEncoder& encoder, const rhi::Texture& texture, uint32_t mipLevel) {
    Readback out;
    const uint32_t w = std::max(1u, texture.width() >> mipLevel), h = std::max(1u, texture.height() >> mipLevel);
    out.size_ = uint64_t(w) * h * rhi::formatInfo(texture.format()).bytesPerPixel;
    out.staging_ = recordStaging(encoder, out.size_);
    encoder.copyTextureToBuffer({.texture = texture, .mipLevel = mipLevel}, {.buffer = out.staging_});
    encoder.bufferBarrier({{out.staging_, rhi::ResourceState::CopyDst, rhi::ResourceState::HostRead}});
    return out;
}

std::vector<std::byte> Readback::bytes() const {
    std::vector<std::byte> out(size_);
    staging_.read(out);
    return out;
}

} // namespace hush::test
