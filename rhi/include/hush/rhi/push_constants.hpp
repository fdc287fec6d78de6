#pragma once
// PushConstants: a pipeline's push-constant values, written by member name and
// checked against the block the shader declares (its reflection): the name must be
// a member, the value its type and size. There is no C++ mirror of the GLSL block to
// drift from it: the shader's member names are the only spelling, and a member never
// written is an error before the first dispatch, not a silent zero.
//
//   rhi::PushConstants params(pipeline);
//   params.set("alpha", 0.2f).set("levels", 5u);            // checked now
//   auto frame = params.slot("frame", rhi::ScalarType::Uint32);
//   ...every frame: params.set(frame, n); pass.setPushConstants(params);
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string_view>

#include <hush/rhi/pipeline.hpp>
#include <hush/rhi/shader.hpp>

namespace hush::rhi {

class PushConstants {
public:
    static constexpr uint32_t kMaxBytes = 128;   // Vulkan's guaranteed maxPushConstantsSize
    static constexpr uint32_t kMaxMembers = 32;

    PushConstants() = default;
    // Throws hush::Error (Unsupported) when the block exceeds kMaxBytes or kMaxMembers.
    explicit PushConstants(const ComputePipeline& pipeline);

    // Writes a scalar member. Throws hush::Error (BindingMismatch) naming the pipeline
    // and the member when there is no such member (listing those there are) or it is
    // not of this type (bool writes a uint 0 / 1).
    PushConstants& set(std::string_view member, float value);
    PushConstants& set(std::string_view member, int32_t value);
    PushConstants& set(std::string_view member, uint32_t value);
    PushConstants& set(std::string_view member, bool value) { return set(member, uint32_t(value ? 1 : 0)); }
    // A vector member (vec2 .. vec4, given as floats).
    PushConstants& set(std::string_view member, std::initializer_list<float> values);
    // A uint vector or array of uint vectors, all its components in order.
    PushConstants& set(std::string_view member, std::span<const uint32_t> values);
    bool has(std::string_view member) const { return find(member) != nullptr; }

    // A member written later, every frame: resolved (and type-checked) now, so that
    // writing it searches and allocates nothing. `values`: its component count
    // (vec4: 4; vec4 m[4]: 16).
    struct Slot {
        uint32_t offset = 0;
        uint32_t member = 0;
        uint32_t values = 1;
    };
    Slot slot(std::string_view member, ScalarType type, uint32_t values = 1) const;
    void set(Slot slot, float value) { write(slot, &value, 1); }
    void set(Slot slot, int32_t value) { write(slot, &value, 1); }
    void set(Slot slot, uint32_t value) { write(slot, &value, 1); }
    // Throws hush::Error (BindingMismatch) unless the span has the slot's component count.
    void set(Slot slot, std::span<const float> values) { write(slot, values.data(), uint32_t(values.size())); }
    void set(Slot slot, std::span<const int32_t> values) { write(slot, values.data(), uint32_t(values.size())); }
    void set(Slot slot, std::span<const uint32_t> values) { write(slot, values.data(), uint32_t(values.size())); }

    // Throws hush::Error (BindingMismatch) naming the first member never written.
    void requireComplete() const;
    bool complete() const { return written_ == allMembers_; }
    const std::byte* data() const { return bytes_.data(); }
    uint32_t size() const { return size_; }
    const ComputePipeline& pipeline() const { return pipeline_; }

private:
    const PushConstantMember* find(std::string_view member) const;
    const PushConstantMember& require(std::string_view member, ScalarType type, uint32_t values) const;
    void write(Slot slot, const void* values, uint32_t count);

    ComputePipeline pipeline_;
    std::array<std::byte, kMaxBytes> bytes_{};
    uint32_t size_ = 0;
    uint64_t allMembers_ = 0;
    uint64_t written_ = 0;
};

} // namespace hush::rhi
