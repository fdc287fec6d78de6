// ComputePipeline with layout "auto" (reflected) or an explicit layout that the
// shader's reflected bindings are checked against.
#include "objects.hpp"
#include "specialization.hpp"
#include "vk_check.hpp"

namespace hush::rhi {
namespace detail {

std::shared_ptr<BindGroupLayoutImpl> createBindGroupLayoutImpl(const std::shared_ptr<DeviceImpl>& device,
                                                               const std::string& label, const std::string& origin,
                                                               const std::vector<BindGroupLayoutEntry>& entries);

ComputePipelineImpl::~ComputePipelineImpl() {
    if (pipeline != VK_NULL_HANDLE) device->vk.vkDestroyPipeline(device->device, pipeline, nullptr);
    if (layout != VK_NULL_HANDLE) device->vk.vkDestroyPipelineLayout(device->device, layout, nullptr);
}

namespace {

bool compatible(const BindGroupLayoutEntry& shader, const BindGroupLayoutEntry& layout) {
    if (shader.kind == BindingKind::ReadOnlyStorageBuffer || shader.kind == BindingKind::StorageBuffer) {
        // A read-only use fits a read-write slot; a write needs a writable one.
        return layout.kind == BindingKind::StorageBuffer ||
               (layout.kind == BindingKind::ReadOnlyStorageBuffer && shader.kind == BindingKind::ReadOnlyStorageBuffer);
    }
    if (shader.kind != layout.kind) return false;
    return shader.kind != BindingKind::StorageTexture || shader.storageFormat == layout.storageFormat;
}

void checkExplicitLayout(const ComputePipelineImpl& p, const ShaderReflection& reflection) {
    for (uint32_t set = 0; set < reflection.sets.size(); ++set) {
        for (const auto& need : reflection.sets[set]) {
            const std::string where = "pipeline '" + p.label + "' set " + std::to_string(set) + " binding " +
                                      std::to_string(need.binding) + " ('" + need.name + "')";
            if (set >= p.setLayouts.size())
                fail(ErrorKind::BindingMismatch, where + ": the explicit layout has only " +
                                                     std::to_string(p.setLayouts.size()) + " bind group layouts");
            const BindGroupLayoutEntry* have = nullptr;
            for (const auto& e : p.setLayouts[set]->entries)
                if (e.binding == need.binding) have = &e;
            if (!have)
                fail(ErrorKind::BindingMismatch, where + ": the shader uses " + describe(need) + ", but " +
                                                     p.setLayouts[set]->origin + " has no such binding");
            if (!compatible(need, *have))
                fail(ErrorKind::BindingMismatch, where + ": the shader uses " + describe(need) + ", but " +
                                                     p.setLayouts[set]->origin + " declares " + describe(*have));
        }
    }
    if (reflection.pushConstantBytes > p.pushConstantBytes)
        fail(ErrorKind::BindingMismatch, "pipeline '" + p.label + "': the shader reads " +
                                             std::to_string(reflection.pushConstantBytes) +
                                             " bytes of push constants, the explicit layout declares " +
                                             std::to_string(p.pushConstantBytes));
}

} // namespace
} // namespace detail

using namespace detail;

ComputePipeline Device::createComputePipeline(const ComputePipelineDesc& desc) const {
    auto* device = checked(impl_, "Device");
    auto* module = checked(desc.module.shared(), "ShaderModule");
    const auto& reflection = module->reflection;
    if (desc.entryPoint != reflection.entryPoint)
        fail(ErrorKind::InvalidArgument, "pipeline '" + desc.label + "': shader '" + module->label +
                                             "' has no compute entry point '" + desc.entryPoint + "' (it has '" +
                                             reflection.entryPoint + "')");
    // Checked before any Vulkan object exists: a wrong constant creates nothing.
    const Specialization specialization = specialize(desc.label, reflection, desc.constants);
    auto impl = std::make_shared<ComputePipelineImpl>();
    impl->device = impl_;
    impl->constants = desc.constants;
    impl->module = desc.module.shared();
    impl->label = desc.label;
    impl->workgroupSize = reflection.workgroupSize;
    impl->shaderPushConstantBytes = reflection.pushConstantBytes;
    for (const auto& set : reflection.sets) impl->setUsed.push_back(!set.empty());

    if (desc.layout) {
        for (const auto& layout : desc.layout->bindGroupLayouts) {
            checked(layout.shared(), "BindGroupLayout");
            impl->setLayouts.push_back(layout.shared());
        }
        impl->pushConstantBytes = desc.layout->pushConstantBytes;
        checkExplicitLayout(*impl, reflection);
        impl->setUsed.resize(impl->setLayouts.size(), false);
    } else {
        for (uint32_t set = 0; set < reflection.sets.size(); ++set)
            impl->setLayouts.push_back(createBindGroupLayoutImpl(
                impl_, desc.label + ".set" + std::to_string(set),
                "pipeline '" + desc.label + "' set " + std::to_string(set), reflection.sets[set]));
        impl->pushConstantBytes = reflection.pushConstantBytes;
    }
    if (impl->pushConstantBytes > device->limits.maxPushConstantsSize)
        fail(ErrorKind::Unsupported, "pipeline '" + desc.label + "' needs " + std::to_string(impl->pushConstantBytes) +
                                         " bytes of push constants; the adapter allows " +
                                         std::to_string(device->limits.maxPushConstantsSize));
    if (impl->setLayouts.size() > device->limits.maxBoundDescriptorSets)
        fail(ErrorKind::Unsupported, "pipeline '" + desc.label + "' uses " + std::to_string(impl->setLayouts.size()) +
                                         " bind groups; the adapter allows " +
                                         std::to_string(device->limits.maxBoundDescriptorSets));

    std::vector<VkDescriptorSetLayout> setLayouts;
    for (const auto& l : impl->setLayouts) setLayouts.push_back(l->layout);
    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, impl->pushConstantBytes};
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = uint32_t(setLayouts.size());
    layoutInfo.pSetLayouts = setLayouts.data();
    layoutInfo.pushConstantRangeCount = impl->pushConstantBytes ? 1 : 0;
    layoutInfo.pPushConstantRanges = &range;
    checkVk(device->vk.vkCreatePipelineLayout(device->device, &layoutInfo, nullptr, &impl->layout),
            "vkCreatePipelineLayout for pipeline '" + desc.label + "'");

    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module->module;
    info.stage.pName = desc.entryPoint.c_str();
    info.stage.pSpecializationInfo = specialization.entries.empty() ? nullptr : &specialization.info;
    info.layout = impl->layout;
    checkVk(device->vk.vkCreateComputePipelines(device->device, VK_NULL_HANDLE, 1, &info, nullptr, &impl->pipeline),
            "vkCreateComputePipelines for pipeline '" + desc.label + "'");
    return ComputePipeline(std::move(impl));
}

const std::string& ComputePipeline::label() const { return checked(impl_, "ComputePipeline")->label; }

BindGroupLayout ComputePipeline::getBindGroupLayout(uint32_t set) const {
    auto* impl = checked(impl_, "ComputePipeline");
    if (set >= impl->setLayouts.size())
        fail(ErrorKind::InvalidArgument, "pipeline '" + impl->label + "' has " + std::to_string(impl->setLayouts.size()) +
                                             " bind group layouts; set " + std::to_string(set) + " does not exist");
    return BindGroupLayout(impl->setLayouts[set]);
}

uint32_t ComputePipeline::bindGroupLayoutCount() const {
    return uint32_t(checked(impl_, "ComputePipeline")->setLayouts.size());
}
uint32_t ComputePipeline::pushConstantBytes() const { return checked(impl_, "ComputePipeline")->pushConstantBytes; }
const std::vector<PushConstantMember>& ComputePipeline::pushConstantMembers() const {
    return checked(impl_, "ComputePipeline")->module->reflection.pushConstants;
}
std::array<uint32_t, 3> ComputePipeline::workgroupSize() const {
    return checked(impl_, "ComputePipeline")->workgroupSize;
}

const std::vector<ConstantEntry>& ComputePipeline::constants() const {
    return checked(impl_, "ComputePipeline")->constants;
}

} // namespace hush::rhi
