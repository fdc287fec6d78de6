#include "objects.hpp"
#include "vk_check.hpp"

namespace hush::rhi {
namespace detail {

ShaderModuleImpl::~ShaderModuleImpl() {
    if (module != VK_NULL_HANDLE) device->vk.vkDestroyShaderModule(device->device, module, nullptr);
}

} // namespace detail

using namespace detail;

ShaderModule Device::createShaderModule(const ShaderModuleDesc& desc) const {
    auto* device = checked(impl_, "Device");
    auto impl = std::make_shared<ShaderModuleImpl>();
    impl->device = impl_;
    impl->label = desc.label;
    impl->reflection = reflectComputeShader(desc.code, desc.label);   // also rejects non-SPIR-V
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = desc.code.size_bytes();
    info.pCode = desc.code.data();
    checkVk(device->vk.vkCreateShaderModule(device->device, &info, nullptr, &impl->module),
            "vkCreateShaderModule for shader '" + desc.label + "'");
    return ShaderModule(std::move(impl));
}

const std::string& ShaderModule::label() const { return checked(impl_, "ShaderModule")->label; }
const ShaderReflection& ShaderModule::reflection() const { return checked(impl_, "ShaderModule")->reflection; }

} // namespace hush::rhi
