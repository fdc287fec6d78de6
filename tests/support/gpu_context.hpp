#pragma once
// The test binary's shared GPU context and its validation-message log.
//
// One Instance (validation layer with synchronization validation, never taken from
// the environment) and one Device per test binary, created on first use. Every
// validation message, from hush's instance or from a raw VkInstance an interop test
// makes, goes to one process-wide log. A GPU test opens a ValidationScope first and
// ends with HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope); tests/support/main.cpp fails
// the process if the log holds anything at all when the session ends.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <catch2/catch.hpp>

#include <hush/rhi/rhi.hpp>

namespace hush::test {

struct GpuContext {
    rhi::Instance instance;
    rhi::Adapter adapter;
    rhi::Device device;
    rhi::Queue queue() const { return device.queue(); }
};

// The shared context; created on first call (the adapter honours HUSH_ADAPTER,
// which CTest sets to llvmpipe).
GpuContext& gpu();
// Drops the shared context; main() calls it before its final validation check, so
// that messages from destroying the device are counted too.
void releaseGpu();

// The process-wide validation log.
void recordValidationMessage(const std::string& message);
size_t validationMessageCount();
std::vector<std::string> validationMessagesSince(size_t first);
std::string joinMessages(const std::vector<std::string>& messages);

// Marks where a test starts in the validation log.
class ValidationScope {
public:
    ValidationScope() : first_(validationMessageCount()) {}
    std::vector<std::string> messages() const { return validationMessagesSince(first_); }

private:
    size_t first_;
};

// The check every GPU test ends with: no validation message since `scope` opened.
#define HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope)                                        \
    do {                                                                                  \
        const auto hush_messages_ = (scope).messages();                                   \
        INFO("validation messages:\n" << ::hush::test::joinMessages(hush_messages_));     \
        REQUIRE(hush_messages_.empty());                                                  \
    } while (false)

// Shaders and pipelines from tests/shaders (layout: auto unless `layout` is given).
rhi::ShaderModule shaderModule(std::string_view name);
rhi::ComputePipeline computePipeline(std::string_view name, const std::string& label = {},
                                     std::optional<rhi::PipelineLayoutDesc> layout = std::nullopt);

// Byte views and conversions for uploads and read-backs.
template <class T> std::span<const std::byte> bytesOf(const std::vector<T>& values) {
    return std::as_bytes(std::span<const T>(values));
}
template <class T> std::vector<T> valuesOf(const std::vector<std::byte>& bytes) {
    std::vector<T> out(bytes.size() / sizeof(T));
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
    return out;
}

// A deterministic pseudo-random sequence (64-bit LCG, top bits), for test data.
class Lcg {
public:
    explicit Lcg(uint64_t seed) : state_(seed * 6364136223846793005ull + 1442695040888963407ull) {}
    uint32_t next() {
        state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
        return uint32_t(state_ >> 32);
    }
    // Uniform in [lo, hi).
    float uniform(float lo, float hi) { return lo + (hi - lo) * float(next() >> 8) * (1.0f / 16777216.0f); }

private:
    uint64_t state_;
};

// Records `record` into a fresh encoder, submits it and waits.
template <class F> void submitAndWait(F&& record, const std::string& label = "test") {
    auto encoder = gpu().device.createCommandEncoder({.label = label});
    record(encoder);
    auto queue = gpu().queue();
    queue.wait(queue.submit(encoder.finish()));
}

// Reads `size` bytes of a buffer in its own submission: barrier from `state` to
// CopySrc, copy into a MapRead buffer, barrier back to `state`.
std::vector<std::byte> readBufferMapped(const rhi::Buffer& buffer, uint64_t offset, uint64_t size,
                                        rhi::ResourceState state);

// A read-back recorded into the caller's own command buffer, right after its work, so
// that synchronization validation checks the caller's barriers against the copy (it
// does not look across submissions that the host waited for). The source must already
// be in CopySrc state. Read the result once the submission has completed.
class Readback {
public:
    static Readback ofBuffer(rhi::CommandEncoder& encoder, const rhi::Buffer& buffer, uint64_t offset, uint64_t size);
    static Readback ofTexture(rhi::CommandEncoder& encoder, const rhi::Texture& texture, uint32_t mipLevel = 0);

    std::vector<std::byte> bytes() const;
    template <class T> std::vector<T> values() const { return valuesOf<T>(bytes()); }

private:
    rhi::Buffer staging_;
    uint64_t size_ = 0;
};

// Runs `f` and returns the hush::Error it throws, or nothing if it returns.
template <class F> std::optional<hush::Error> errorFrom(F&& f) {
    try {
        f();
    } catch (const hush::Error& e) {
        return e;
    }
    return std::nullopt;
}

} // namespace hush::test

namespace Catch {
template <> struct StringMaker<hush::ErrorKind> {
    static std::string convert(hush::ErrorKind kind) { return hush::toString(kind); }
};
template <> struct StringMaker<hush::rhi::BindGroupLayoutEntry> {
    static std::string convert(const hush::rhi::BindGroupLayoutEntry& e) {
        return "{binding " + std::to_string(e.binding) + ", " + hush::rhi::describe(e) + ", name '" + e.name +
               "', format " + std::string(hush::rhi::toString(e.storageFormat)) + ", access " +
               std::string(hush::rhi::toString(e.access)) + ", count " + std::to_string(e.count) + "}";
    }
};
} // namespace Catch
