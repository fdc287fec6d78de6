#pragma once
// ShaderModule: SPIR-V words plus what SPIRV-Cross reflected from them.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <hush/rhi/bind_group.hpp>

namespace hush::rhi {

struct ShaderReflection {
    std::string entryPoint;
    std::array<uint32_t, 3> workgroupSize = {1, 1, 1};
    // sets[s] lists the bindings of descriptor set s, sorted by binding.
    std::vector<std::vector<BindGroupLayoutEntry>> sets;
    uint32_t pushConstantBytes = 0;
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
