#pragma once
// ShaderModule: SPIR-V words plus what SPIRV-Cross reflected from them.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <hush/rhi/bind_group.hpp>

namespace hush::rhi {

// A member of the shader's push-constant block, as reflected: what the C++ side must
// write, by name (rhi/push_constants.hpp checks every write against this).
enum class ScalarType : uint8_t { Float32, Int32, Uint32 };
std::string_view toString(ScalarType type);
struct PushConstantMember {
    std::string name;
    uint32_t offset = 0;                      // bytes from the block's start
    ScalarType type = ScalarType::Float32;
    uint32_t components = 1;                  // 1 (scalar) to 4 (vec4)
    uint32_t arraySize = 1;                   // > 1: an array of tightly packed vectors (uvec4 codes[2])
    friend bool operator==(const PushConstantMember&, const PushConstantMember&) = default;
};

// A specialization constant (GLSL `layout(constant_id = N) const`; WebGPU's pipeline-
// overridable constant): fixed when a pipeline is made (ComputePipelineDesc::constants),
// so that the driver compiles the shader with the value folded in: loops over it get
// constant bounds, branches on it vanish. What push constants cannot do.
struct ShaderConstant {
    std::string name;
    uint32_t id = 0;                         // the constant_id
    ScalarType type = ScalarType::Uint32;
    double defaultValue = 0.0;               // the shader's own value
    friend bool operator==(const ShaderConstant&, const ShaderConstant&) = default;
};

struct ShaderReflection {
    std::string entryPoint;
    std::array<uint32_t, 3> workgroupSize = {1, 1, 1};
    // sets[s] lists the bindings of descriptor set s, sorted by binding.
    std::vector<std::vector<BindGroupLayoutEntry>> sets;
    uint32_t pushConstantBytes = 0;
    std::vector<PushConstantMember> pushConstants;   // in offset order
    std::vector<ShaderConstant> constants;           // in constant_id order
};

// Reflects a compute shader. Throws hush::Error naming `label` on invalid SPIR-V.
ShaderReflection reflectComputeShader(std::span<const uint32_t> spirv, const std::string& label);

struct ShaderModuleDesc {
    std::string label;
    std::span<const uint32_t> code;   // SPIR-V words, e.g. hush::shaders::find("...")
};

class ShaderModule : public Handle<detail::ShaderModuleImpl> {
public:
    using Handle::Handle;
    const std::string& label() const;
    const ShaderReflection& reflection() const;
};

} // namespace hush::rhi
