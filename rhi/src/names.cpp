// Text for hush's enums: what error messages, dumps and the CLI print.
#include <algorithm>

#include <hush/rhi/bind_group.hpp>
#include <hush/core/error.hpp>
#include <hush/rhi/format.hpp>
#include <hush/rhi/instance.hpp>
#include <hush/rhi/resource_state.hpp>
#include <hush/rhi/shader.hpp>


namespace hush::rhi {

const FormatInfo& formatInfo(Format format) {
    static const FormatInfo kInfo[] = {
        {"undefined", "", 0, 0, ChannelType::Float32},
        {"r8unorm", "r8", 1, 1, ChannelType::Unorm8},
        {"r16float", "r16f", 1, 2, ChannelType::Float16},
        {"r32float", "r32f", 1, 4, ChannelType::Float32},
        {"rg16float", "rg16f", 2, 4, ChannelType::Float16},
        {"rg32float", "rg32f", 2, 8, ChannelType::Float32},
        {"rgba8unorm", "rgba8", 4, 4, ChannelType::Unorm8},
        {"rgba16float", "rgba16f", 4, 8, ChannelType::Float16},
        {"rgba32float", "rgba32f", 4, 16, ChannelType::Float32},
        {"r32uint", "r32ui", 1, 4, ChannelType::Uint32},
    };
    const auto index = size_t(format);
    return index < std::size(kInfo) ? kInfo[index] : kInfo[0];
}

Format parseFormat(std::string_view name) {
    for (Format f : kAllFormats) {
        const auto& info = formatInfo(f);
        if (info.name == name || info.glslName == name) return f;
    }
    return Format::Undefined;
}

namespace {
template <class E>
std::string flagsToString(E value, std::initializer_list<std::pair<E, const char*>> names) {
    std::string out;
    for (auto [bit, name] : names) {
        if (hasAny(value, bit)) {
            if (!out.empty()) out += '|';
            out += name;
        }
    }
    return out.empty() ? "none" : out;
}
} // namespace

std::string toString(TextureUsage usage) {
    return flagsToString(usage, {{TextureUsage::CopySrc, "copy-src"},
                                 {TextureUsage::CopyDst, "copy-dst"},
                                 {TextureUsage::TextureBinding, "texture-binding"},
                                 {TextureUsage::StorageBinding, "storage-binding"}});
}

std::string toString(BufferUsage usage) {
    return flagsToString(usage, {{BufferUsage::MapRead, "map-read"},
                                 {BufferUsage::MapWrite, "map-write"},
                                 {BufferUsage::CopySrc, "copy-src"},
                                 {BufferUsage::CopyDst, "copy-dst"},
                                 {BufferUsage::Uniform, "uniform"},
                                 {BufferUsage::Storage, "storage"},
                                 {BufferUsage::Indirect, "indirect"}});
}

std::string_view toString(ResourceState state) {
    switch (state) {
    case ResourceState::Undefined: return "undefined";
    case ResourceState::CopySrc: return "copy-src";
    case ResourceState::CopyDst: return "copy-dst";
    case ResourceState::SampledRead: return "sampled-read";
    case ResourceState::StorageRead: return "storage-read";
    case ResourceState::StorageWrite: return "storage-write";
    case ResourceState::StorageReadWrite: return "storage-read-write";
    case ResourceState::UniformRead: return "uniform-read";
    case ResourceState::IndirectRead: return "indirect-read";
    case ResourceState::HostRead: return "host-read";
    case ResourceState::HostWrite: return "host-write";
    case ResourceState::General: return "general";
    }
    return "unknown";
}

bool isReadOnly(ResourceState state) {
    switch (state) {
    case ResourceState::CopySrc:
    case ResourceState::SampledRead:
    case ResourceState::StorageRead:
    case ResourceState::UniformRead:
    case ResourceState::IndirectRead:
    case ResourceState::HostRead: return true;
    default: return false;
    }
}

std::string_view toString(AdapterType type) {
    switch (type) {
    case AdapterType::DiscreteGpu: return "discrete GPU";
    case AdapterType::IntegratedGpu: return "integrated GPU";
    case AdapterType::VirtualGpu: return "virtual GPU";
    case AdapterType::Cpu: return "CPU";
    case AdapterType::Other: return "other";
    }
    return "other";
}

std::string_view toString(ScalarType type) {
    switch (type) {
    case ScalarType::Float32: return "float";
    case ScalarType::Int32: return "int";
    case ScalarType::Uint32: return "uint";
    }
    return "unknown";
}

std::string_view toString(BindingKind kind) {
    switch (kind) {
    case BindingKind::UniformBuffer: return "uniform buffer";
    case BindingKind::StorageBuffer: return "storage buffer";
    case BindingKind::ReadOnlyStorageBuffer: return "read-only storage buffer";
    case BindingKind::SampledTexture: return "sampled texture";
    case BindingKind::CombinedTextureSampler: return "combined texture+sampler";
    case BindingKind::StorageTexture: return "storage texture";
    case BindingKind::Sampler: return "sampler";
    }
    return "unknown";
}

std::string_view toString(StorageAccess access) {
    switch (access) {
    case StorageAccess::ReadWrite: return "read-write";
    case StorageAccess::ReadOnly: return "read-only";
    case StorageAccess::WriteOnly: return "write-only";
    }
    return "read-write";
}

std::string describe(const BindGroupLayoutEntry& entry) {
    std::string out(toString(entry.kind));
    if (entry.kind == BindingKind::StorageTexture) {
        out += ' ';
        out += toString(entry.storageFormat);
        out += " (";
        out += toString(entry.access);
        out += ')';
    }
    return out;
}

} // namespace hush::rhi
