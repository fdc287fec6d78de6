#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <hush/rhi/bind_group.hpp>
#include <hush/rhi/shader.hpp>

namespace hush::rhi {

// An explicit layout, for sharing bind groups between pipelines. The shader's
// reflected bindings must each be present in it with the same kind and format.
struct PipelineLayoutDesc {
    std::vector<BindGroupLayout> bindGroupLayouts;
    uint32_t pushConstantBytes = 0;
};

// The value of one of the shader's specialization constants (ShaderConstant), by name,
// as WebGPU's and Dawn's ConstantEntry: a double that must be exactly representable in
// the constant's type (a whole number for int and uint, finite for float).
struct ConstantEntry {
    std::string key;
    double value = 0.0;
    friend bool operator==(const ConstantEntry&, const ConstantEntry&) = default;
};

struct ComputePipelineDesc {
    std::string label;
    ShaderModule module;
    std::string entryPoint = "main";
    std::optional<PipelineLayoutDesc> layout;   // empty: layout "auto", reflected
    std::vector<ConstantEntry> constants;       // constants not named keep the shader's value
};

class ComputePipeline : public Handle<detail::ComputePipelineImpl> {
public:
    using Handle::Handle;
    const std::string& label() const;
    // The layout of descriptor set `set` (reflected or explicit).
    BindGroupLayout getBindGroupLayout(uint32_t set) const;
    uint32_t bindGroupLayoutCount() const;
    uint32_t pushConstantBytes() const;
    // The shader's push-constant block, member by member (rhi/push_constants.hpp).
    const std::vector<PushConstantMember>& pushConstantMembers() const;
    std::array<uint32_t, 3> workgroupSize() const;
    // The constants this pipeline was made with (ComputePipelineDesc::constants).
    const std::vector<ConstantEntry>& constants() const;
};

} // namespace hush::rhi
