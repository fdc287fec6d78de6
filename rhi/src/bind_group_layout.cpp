#include "objects.hpp"
#include "vk_check.hpp"
#include "vk_convert.hpp"

namespace hush::rhi {
namespace detail {

BindGroupLayoutImpl::~BindGroupLayoutImpl() {
    if (layout != VK_NULL_HANDLE) device->vk.vkDestroyDescriptorSetLayout(device->device, layout, nullptr);
}

std::shared_ptr<BindGroupLayoutImpl> createBindGroupLayoutImpl(const std::shared_ptr<DeviceImpl>& device,
                                                               const std::string& label, const std::string& origin,
                                                               const std::vector<BindGroupLayoutEntry>& entries) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (size_t i = 0; i < entries.size(); ++i) {
        const auto& e = entries[i];
        for (size_t j = 0; j < i; ++j)
            if (entries[j].binding == e.binding)
                fail(ErrorKind::InvalidArgument, origin + " lists binding " + std::to_string(e.binding) + " twice");
        if (e.kind == BindingKind::StorageTexture && e.storageFormat == Format::Undefined)
            fail(ErrorKind::InvalidArgument, origin + " binding " + std::to_string(e.binding) +
                                                 " is a storage texture without a storageFormat");
        if (e.count != 1)
            fail(ErrorKind::Unsupported, origin + " binding " + std::to_string(e.binding) +
                                             ": descriptor arrays are not supported");
        VkDescriptorSetLayoutBinding b{};
        b.binding = e.binding;
        b.descriptorType = toVkDescriptorType(e.kind);
        b.descriptorCount = 1;
        b.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
        bindings.push_back(b);
    }
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(bindings.size());
    info.pBindings = bindings.data();
    auto impl = std::make_shared<BindGroupLayoutImpl>();
    impl->device = device;
    impl->label = label;
    impl->origin = origin;
    impl->entries = entries;
    checkVk(device->vk.vkCreateDescriptorSetLayout(device->device, &info, nullptr, &impl->layout),
            "vkCreateDescriptorSetLayout for " + origin);
    return impl;
}

} // namespace detail

using namespace detail;

BindGroupLayout Device::createBindGroupLayout(const BindGroupLayoutDesc& desc) const {
    checked(impl_, "Device");
    return BindGroupLayout(
        createBindGroupLayoutImpl(impl_, desc.label, "bind group layout '" + desc.label + "'", desc.entries));
}

const std::string& BindGroupLayout::label() const { return checked(impl_, "BindGroupLayout")->label; }
const std::vector<BindGroupLayoutEntry>& BindGroupLayout::entries() const {
    return checked(impl_, "BindGroupLayout")->entries;
}

const BindGroupLayoutEntry* BindGroupLayout::findBinding(uint32_t binding) const {
    for (const auto& e : entries())
        if (e.binding == binding) return &e;
    return nullptr;
}

const BindGroupLayoutEntry* BindGroupLayout::findName(std::string_view name) const {
    for (const auto& e : entries())
        if (e.name == name) return &e;
    return nullptr;
}

} // namespace hush::rhi
