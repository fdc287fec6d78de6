#include <hush/rhi/push_constants.hpp>

#include <cstring>

#include <hush/core/error.hpp>

namespace hush::rhi {

PushConstants::PushConstants(const ComputePipeline& pipeline) : pipeline_(pipeline) {
    const auto& members = pipeline.pushConstantMembers();
    size_ = pipeline.pushConstantBytes();
    if (size_ > kMaxBytes || members.size() > kMaxMembers)
        throw Error(ErrorKind::Unsupported, "pipeline '" + pipeline.label() + "': its push-constant block (" +
                                                std::to_string(size_) + " bytes, " + std::to_string(members.size()) +
                                                " members) exceeds hush's " + std::to_string(kMaxBytes) + " bytes / " +
                                                std::to_string(kMaxMembers) + " members");
    allMembers_ = (1ull << members.size()) - 1;
}

const PushConstantMember* PushConstants::find(std::string_view member) const {
    if (!pipeline_) return nullptr;
    for (const auto& m : pipeline_.pushConstantMembers())
        if (m.name == member) return &m;
    return nullptr;
}

const PushConstantMember& PushConstants::require(std::string_view member, ScalarType type, uint32_t values) const {
    const std::string where = "pipeline '" + (pipeline_ ? pipeline_.label() : std::string("(none)")) + "'";
    const PushConstantMember* m = find(member);
    if (!m) {
        std::string names;
        if (pipeline_)
            for (const auto& other : pipeline_.pushConstantMembers()) names += (names.empty() ? "" : ", ") + other.name;
        throw Error(ErrorKind::BindingMismatch, where + " has no push constant '" + std::string(member) +
                                                    "'; its push constants: " + (names.empty() ? "none" : names));
    }
    if (m->type != type || m->components * m->arraySize != values) {
        auto text = [](ScalarType t, uint32_t n) {
            return n == 1 ? std::string(toString(t)) : std::to_string(n) + " x " + std::string(toString(t));
        };
        throw Error(ErrorKind::BindingMismatch, where + ": push constant '" + m->name + "' is " +
                                                    text(m->type, m->components * m->arraySize) +
                                                    " in the shader, written as " + text(type, values));
    }
    return *m;
}

PushConstants::Slot PushConstants::slot(std::string_view member, ScalarType type, uint32_t values) const {
    const auto& m = require(member, type, values);
    return {m.offset, uint32_t(&m - pipeline_.pushConstantMembers().data()), values};
}

void PushConstants::write(Slot slot, const void* values, uint32_t count) {
    if (count != slot.values)
        throw Error(ErrorKind::BindingMismatch, "pipeline '" + pipeline_.label() + "': push constant #" +
                                                    std::to_string(slot.member) + " takes " +
                                                    std::to_string(slot.values) + " values, written with " +
                                                    std::to_string(count));
    std::memcpy(bytes_.data() + slot.offset, values, 4 * size_t(count));
    written_ |= 1ull << slot.member;
}

PushConstants& PushConstants::set(std::string_view member, float value) {
    set(slot(member, ScalarType::Float32), value);
    return *this;
}
PushConstants& PushConstants::set(std::string_view member, int32_t value) {
    set(slot(member, ScalarType::Int32), value);
    return *this;
}
PushConstants& PushConstants::set(std::string_view member, uint32_t value) {
    set(slot(member, ScalarType::Uint32), value);
    return *this;
}

PushConstants& PushConstants::set(std::string_view member, std::initializer_list<float> values) {
    const auto& m = require(member, ScalarType::Float32, uint32_t(values.size()));
    std::memcpy(bytes_.data() + m.offset, values.begin(), values.size() * sizeof(float));
    written_ |= 1ull << (&m - pipeline_.pushConstantMembers().data());
    return *this;
}

PushConstants& PushConstants::set(std::string_view member, std::span<const uint32_t> values) {
    const auto& m = require(member, ScalarType::Uint32, uint32_t(values.size()));
    std::memcpy(bytes_.data() + m.offset, values.data(), values.size_bytes());
    written_ |= 1ull << (&m - pipeline_.pushConstantMembers().data());
    return *this;
}

void PushConstants::requireComplete() const {
    if (complete()) return;
    const auto& members = pipeline_.pushConstantMembers();
    for (size_t i = 0; i < members.size(); ++i)
        if (!(written_ & (1ull << i)))
            throw Error(ErrorKind::BindingMismatch, "pipeline '" + pipeline_.label() + "': push constant '" +
                                                        members[i].name + "' is never written");
}

} // namespace hush::rhi
