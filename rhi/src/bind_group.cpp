// BindGroup: one descriptor set, checked entry by entry against its layout so that
// a mismatch is reported in hush's terms (pipeline, set, binding, both kinds).
#include <algorithm>

#include "objects.hpp"
#include "vk_check.hpp"
#include "vk_convert.hpp"

namespace hush::rhi {
namespace detail {

BindGroupImpl::~BindGroupImpl() {
    if (pool != VK_NULL_HANDLE) device->vk.vkDestroyDescriptorPool(device->device, pool, nullptr);
}

namespace {

std::string listBindings(const std::vector<BindGroupLayoutEntry>& entries) {
    std::string out;
    for (const auto& e : entries) {
        if (!out.empty()) out += ", ";
        out += std::to_string(e.binding) + " '" + e.name + "' (" + describe(e) + ")";
    }
    return out.empty() ? "no bindings" : out;
}

// What the caller handed over, in the words of error messages.
std::string describeGiven(const BindGroupEntry& e, const TextureView& view) {
    std::string out;
    if (e.buffer) out = "buffer '" + e.buffer.label() + "' (usage " + toString(e.buffer.usage()) + ")";
    if (view) {
        const auto texture = view.texture();
        if (!out.empty()) out += " and ";
        out += "texture '" + texture.label() + "' (" + std::string(toString(texture.format())) + ", usage " +
               toString(texture.usage()) + ")";
    }
    if (e.sampler) {
        if (!out.empty()) out += " and ";
        out += "sampler '" + e.sampler.label() + "'";
    }
    return out.empty() ? "nothing" : out;
}

struct Resolved {
    const BindGroupLayoutEntry* layout = nullptr;
    const BindGroupEntry* entry = nullptr;
    TextureView view;
};

} // namespace

} // namespace detail

using namespace detail;

BindGroup Device::createBindGroup(const BindGroupDesc& desc) const {
    auto* device = checked(impl_, "Device");
    auto* layout = checked(desc.layout.shared(), "BindGroupLayout");
    const std::string what = "bind group '" + desc.label + "' for " + layout->origin;
    auto mismatch = [&](const std::string& message) { fail(ErrorKind::BindingMismatch, what + ": " + message); };

    std::vector<Resolved> resolved;
    for (const auto& entry : desc.entries) {
        const BindGroupLayoutEntry* target = nullptr;
        if (entry.binding != kBindingByName) {
            target = desc.layout.findBinding(entry.binding);
            if (!target)
                mismatch("binding " + std::to_string(entry.binding) + " is not in the layout, which has " +
                         listBindings(layout->entries));
        } else {
            if (entry.name.empty()) mismatch("an entry has neither a binding number nor a name");
            target = desc.layout.findName(entry.name);
            if (!target)
                mismatch("no binding named '" + entry.name + "'; the layout has " + listBindings(layout->entries));
        }
        for (const auto& r : resolved)
            if (r.layout == target) mismatch("binding " + std::to_string(target->binding) + " is set twice");
        TextureView view = entry.textureView ? entry.textureView : (entry.texture ? entry.texture.defaultView() : TextureView{});
        if (view && view.texture().impl()->device.get() != device) mismatch("a texture from another device");
        resolved.push_back({target, &entry, view});
    }
    for (const auto& e : layout->entries) {
        bool found = false;
        for (const auto& r : resolved) found = found || r.layout == &e;
        if (!found) mismatch("binding " + std::to_string(e.binding) + " ('" + e.name + "', " + describe(e) + ") is not set");
    }

    // Kind, usage and format checks, then the descriptor writes.
    std::vector<VkDescriptorPoolSize> poolSizes;
    std::vector<VkWriteDescriptorSet> writes(resolved.size());
    std::vector<VkDescriptorBufferInfo> bufferInfos(resolved.size());
    std::vector<VkDescriptorImageInfo> imageInfos(resolved.size());
    auto impl = std::make_shared<BindGroupImpl>();
    impl->device = impl_;
    impl->layout = desc.layout.shared();
    impl->label = desc.label;
    for (size_t i = 0; i < resolved.size(); ++i) {
        // Named references, not a structured binding: clang 14 cannot capture those.
        const BindGroupLayoutEntry* target = resolved[i].layout;
        const BindGroupEntry* entry = resolved[i].entry;
        const TextureView& view = resolved[i].view;
        const std::string where = "binding " + std::to_string(target->binding) + " ('" + target->name + "')";
        auto expected = [&](const std::string& why) {
            mismatch(where + ": expected " + describe(*target) + ", given " + describeGiven(*entry, view) +
                     (why.empty() ? "" : " (" + why + ")"));
        };
        const auto kind = target->kind;
        const bool wantsBuffer = kind == BindingKind::UniformBuffer || kind == BindingKind::StorageBuffer ||
                                 kind == BindingKind::ReadOnlyStorageBuffer;
        const bool wantsView = kind == BindingKind::SampledTexture || kind == BindingKind::StorageTexture ||
                               kind == BindingKind::CombinedTextureSampler;
        const bool wantsSampler = kind == BindingKind::Sampler || kind == BindingKind::CombinedTextureSampler;
        if (bool(entry->buffer) != wantsBuffer || bool(view) != wantsView || bool(entry->sampler) != wantsSampler)
            expected("");

        auto& write = writes[i];
        write = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.dstBinding = target->binding;
        write.descriptorCount = 1;
        write.descriptorType = toVkDescriptorType(kind);
        if (wantsBuffer) {
            const auto& buffer = entry->buffer;
            const bool uniform = kind == BindingKind::UniformBuffer;
            const auto needed = uniform ? BufferUsage::Uniform : BufferUsage::Storage;
            if (!hasAny(buffer.usage(), needed)) expected("the buffer lacks usage " + toString(needed));
            const uint64_t size = entry->size == kWholeSize ? buffer.size() - std::min(entry->offset, buffer.size()) : entry->size;
            if (entry->offset >= buffer.size() || size == 0 || size > buffer.size() - entry->offset)
                fail(ErrorKind::InvalidArgument, what + ": " + where + ": range [" + std::to_string(entry->offset) +
                                                     ", +" + std::to_string(size) + ") is outside buffer '" +
                                                     buffer.label() + "' (" + std::to_string(buffer.size()) + " bytes)");
            const uint64_t align = uniform ? device->limits.minUniformBufferOffsetAlignment
                                           : device->limits.minStorageBufferOffsetAlignment;
            if (align && entry->offset % align)
                fail(ErrorKind::InvalidArgument, what + ": " + where + ": offset " + std::to_string(entry->offset) +
                                                     " is not a multiple of the adapter's alignment " + std::to_string(align));
            bufferInfos[i] = {buffer.impl()->buffer, entry->offset, size};
            write.pBufferInfo = &bufferInfos[i];
            impl->resources.push_back(buffer.shared());
        } else {
            auto& image = imageInfos[i];
            if (view) {
                const auto texture = view.texture();
                if (kind == BindingKind::StorageTexture) {
                    if (!hasAny(texture.usage(), TextureUsage::StorageBinding))
                        expected("the texture lacks usage storage-binding");
                    if (texture.format() != target->storageFormat) expected("formats differ");
                    image.imageLayout = VK_IMAGE_LAYOUT_GENERAL;
                } else {
                    if (!hasAny(texture.usage(), TextureUsage::TextureBinding))
                        expected("the texture lacks usage texture-binding");
                    image.imageLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
                }
                image.imageView = view.impl()->view;
                impl->resources.push_back(view.shared());
            }
            if (entry->sampler) {
                image.sampler = entry->sampler.impl()->sampler;
                impl->resources.push_back(entry->sampler.shared());
            }
            write.pImageInfo = &image;
        }
        auto size = std::find_if(poolSizes.begin(), poolSizes.end(),
                                 [&](const VkDescriptorPoolSize& s) { return s.type == write.descriptorType; });
        if (size == poolSizes.end()) poolSizes.push_back({write.descriptorType, 1});
        else ++size->descriptorCount;
    }

    if (poolSizes.empty()) poolSizes.push_back({VK_DESCRIPTOR_TYPE_SAMPLER, 1});   // an empty set still needs a pool
    // One small pool per group: bind groups are made at graph compile time, not per frame.
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = uint32_t(poolSizes.size());
    poolInfo.pPoolSizes = poolSizes.data();
    checkVk(device->vk.vkCreateDescriptorPool(device->device, &poolInfo, nullptr, &impl->pool),
            "vkCreateDescriptorPool for " + what);
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = impl->pool;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &layout->layout;
    checkVk(device->vk.vkAllocateDescriptorSets(device->device, &alloc, &impl->set), "vkAllocateDescriptorSets for " + what);
    for (auto& w : writes) w.dstSet = impl->set;
    if (!writes.empty()) device->vk.vkUpdateDescriptorSets(device->device, uint32_t(writes.size()), writes.data(), 0, nullptr);
    return BindGroup(std::move(impl));
}

const std::string& BindGroup::label() const { return checked(impl_, "BindGroup")->label; }
BindGroupLayout BindGroup::layout() const { return BindGroupLayout(checked(impl_, "BindGroup")->layout); }

} // namespace hush::rhi
