// layout: auto. SPIRV-Cross reads the descriptor sets, bindings, image formats,
// access qualifiers, push-constant size and workgroup size out of the SPIR-V.
#include <algorithm>
#include <map>

#include <spirv_cross/spirv_cross.hpp>

#include <hush/core/error.hpp>
#include <hush/rhi/shader.hpp>

namespace hush::rhi {

namespace {

Format fromSpirvFormat(spv::ImageFormat format) {
    switch (format) {
    case spv::ImageFormatR8: return Format::R8Unorm;
    case spv::ImageFormatR16f: return Format::R16Float;
    case spv::ImageFormatR32f: return Format::R32Float;
    case spv::ImageFormatRg16f: return Format::RG16Float;
    case spv::ImageFormatRg32f: return Format::RG32Float;
    case spv::ImageFormatRgba8: return Format::RGBA8Unorm;
    case spv::ImageFormatRgba16f: return Format::RGBA16Float;
    case spv::ImageFormatRgba32f: return Format::RGBA32Float;
    case spv::ImageFormatR32ui: return Format::R32Uint;
    default: return Format::Undefined;
    }
}

class Reflector {
public:
    Reflector(std::span<const uint32_t> spirv, const std::string& label)
        : compiler_(spirv.data(), spirv.size()), label_(label) {}

    ShaderReflection run() {
        ShaderReflection out;
        const auto entries = compiler_.get_entry_points_and_stages();
        const auto compute = std::find_if(entries.begin(), entries.end(), [](const spirv_cross::EntryPoint& e) {
            return e.execution_model == spv::ExecutionModelGLCompute;
        });
        if (compute == entries.end())
            throw Error(ErrorKind::InvalidArgument, "shader '" + label_ + "' has no compute entry point");
        out.entryPoint = compute->name;
        compiler_.set_entry_point(compute->name, spv::ExecutionModelGLCompute);
        for (uint32_t i = 0; i < 3; ++i)
            out.workgroupSize[i] = compiler_.get_execution_mode_argument(spv::ExecutionModeLocalSize, i);

        const auto resources = compiler_.get_shader_resources();
        for (const auto& r : resources.uniform_buffers) add(r, BindingKind::UniformBuffer);
        for (const auto& r : resources.storage_buffers) {
            const auto flags = compiler_.get_buffer_block_flags(r.id);
            add(r, flags.get(spv::DecorationNonWritable) ? BindingKind::ReadOnlyStorageBuffer : BindingKind::StorageBuffer);
        }
        for (const auto& r : resources.sampled_images) add(r, BindingKind::CombinedTextureSampler);
        for (const auto& r : resources.separate_images) add(r, BindingKind::SampledTexture);
        for (const auto& r : resources.separate_samplers) add(r, BindingKind::Sampler);
        for (const auto& r : resources.storage_images) add(r, BindingKind::StorageTexture);
        rejectUnsupported(resources.atomic_counters, "atomic counter");
        rejectUnsupported(resources.acceleration_structures, "acceleration structure");
        rejectUnsupported(resources.subpass_inputs, "subpass input");
        for (const auto& r : resources.push_constant_buffers) {
            const auto& type = compiler_.get_type(r.base_type_id);
            out.pushConstantBytes = std::max(out.pushConstantBytes, uint32_t(compiler_.get_declared_struct_size(type)));
            addPushConstantMembers(r.base_type_id, out.pushConstants);
        }
        addConstants(out.constants);

        uint32_t setCount = sets_.empty() ? 0 : sets_.rbegin()->first + 1;
        out.sets.resize(setCount);
        for (auto& [set, bindings] : sets_) {
            std::sort(bindings.begin(), bindings.end(), [](const auto& a, const auto& b) { return a.binding < b.binding; });
            out.sets[set] = bindings;
        }
        return out;
    }

private:
    void add(const spirv_cross::Resource& r, BindingKind kind) {
        BindGroupLayoutEntry entry;
        entry.kind = kind;
        // For buffers SPIRV-Cross's resource name is the block's type name; the name a
        // user writes in a bind group is the variable's (anonymous blocks keep the type's).
        const std::string variable = compiler_.get_name(r.id);
        entry.name = variable.empty() ? r.name : variable;
        entry.binding = compiler_.get_decoration(r.id, spv::DecorationBinding);
        const uint32_t set = compiler_.get_decoration(r.id, spv::DecorationDescriptorSet);
        const auto& type = compiler_.get_type(r.type_id);
        const std::string where = "'" + r.name + "' (set " + std::to_string(set) + ", binding " +
                                  std::to_string(entry.binding) + ") of shader '" + label_ + "'";
        if (!type.array.empty())
            throw Error(ErrorKind::Unsupported, "descriptor arrays are not supported: " + where);
        if (kind == BindingKind::SampledTexture || kind == BindingKind::CombinedTextureSampler ||
            kind == BindingKind::StorageTexture) {
            if (type.image.dim != spv::Dim2D || type.image.arrayed || type.image.ms)
                throw Error(ErrorKind::Unsupported, "only non-arrayed, single-sample 2D images are supported: " + where);
        }
        if (kind == BindingKind::StorageTexture) {
            entry.storageFormat = fromSpirvFormat(type.image.format);
            if (entry.storageFormat == Format::Undefined)
                throw Error(ErrorKind::Unsupported,
                            "storage image " + where + " needs a format qualifier hush supports (r8, r16f, r32f, "
                            "rg16f, rg32f, rgba8, rgba16f, rgba32f, r32ui), e.g. layout(rgba16f)");
            const auto decorations = compiler_.get_decoration_bitset(r.id);
            if (decorations.get(spv::DecorationNonReadable)) entry.access = StorageAccess::WriteOnly;
            else if (decorations.get(spv::DecorationNonWritable)) entry.access = StorageAccess::ReadOnly;
        }
        auto& list = sets_[set];
        for (const auto& other : list)
            if (other.binding == entry.binding)
                throw Error(ErrorKind::InvalidArgument, "two resources share binding: " + where + " and '" + other.name + "'");
        list.push_back(entry);
    }

    // Scalars and vectors of float, int and uint: what hush's shaders pass per dispatch.
    void addPushConstantMembers(spirv_cross::TypeID block, std::vector<PushConstantMember>& out) {
        const auto& type = compiler_.get_type(block);
        for (uint32_t i = 0; i < type.member_types.size(); ++i) {
            const auto& member = compiler_.get_type(type.member_types[i]);
            PushConstantMember m;
            m.name = compiler_.get_member_name(block, i);
            m.offset = compiler_.type_struct_member_offset(type, i);
            m.components = member.vecsize;
            const std::string where = "push constant '" + m.name + "' of shader '" + label_ + "'";
            if (member.columns != 1 || member.array.size() > 1)
                throw Error(ErrorKind::Unsupported, where + " is a matrix or a nested array; hush passes scalars, "
                                                            "vectors and arrays of them");
            if (!member.array.empty()) {
                m.arraySize = member.array[0];
                // Only arrays without gaps between elements (vec4s in std430).
                if (compiler_.type_struct_member_array_stride(type, i) != 4 * m.components)
                    throw Error(ErrorKind::Unsupported, where + " is an array with padding; use an array of 4-vectors");
            }
            switch (member.basetype) {
            case spirv_cross::SPIRType::Float: m.type = ScalarType::Float32; break;
            case spirv_cross::SPIRType::Int: m.type = ScalarType::Int32; break;
            case spirv_cross::SPIRType::UInt: m.type = ScalarType::Uint32; break;
            default: throw Error(ErrorKind::Unsupported, where + " is not a float, int or uint (vector)");
            }
            out.push_back(std::move(m));
        }
    }

    // Scalar float, int and uint constants: booleans and composites have no use in hush yet.
    void addConstants(std::vector<ShaderConstant>& out) {
        for (const auto& c : compiler_.get_specialization_constants()) {
            const auto& constant = compiler_.get_constant(c.id);
            const auto& type = compiler_.get_type(constant.constant_type);
            ShaderConstant sc{.name = compiler_.get_name(c.id), .id = c.constant_id};
            const std::string where = "specialization constant " + std::to_string(c.constant_id) + " ('" + sc.name +
                                      "') of shader '" + label_ + "'";
            if (sc.name.empty()) throw Error(ErrorKind::Unsupported, where + " has no name; pipelines set constants by name");
            if (type.vecsize != 1 || type.columns != 1)
                throw Error(ErrorKind::Unsupported, where + " is not a scalar");
            switch (type.basetype) {
            case spirv_cross::SPIRType::Float: sc.type = ScalarType::Float32; sc.defaultValue = constant.scalar_f32(); break;
            case spirv_cross::SPIRType::Int: sc.type = ScalarType::Int32; sc.defaultValue = constant.scalar_i32(); break;
            case spirv_cross::SPIRType::UInt: sc.type = ScalarType::Uint32; sc.defaultValue = constant.scalar(); break;
            default: throw Error(ErrorKind::Unsupported, where + " is not a float, int or uint (use a uint for a flag)");
            }
            out.push_back(std::move(sc));
        }
        std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
    }

    void rejectUnsupported(const spirv_cross::SmallVector<spirv_cross::Resource>& list, const char* what) {
        if (!list.empty())
            throw Error(ErrorKind::Unsupported, std::string("shader '") + label_ + "' uses a " + what + " ('" +
                                                    list.front().name + "'), which hush does not support");
    }

    spirv_cross::Compiler compiler_;
    std::string label_;
    std::map<uint32_t, std::vector<BindGroupLayoutEntry>> sets_;
};

} // namespace

ShaderReflection reflectComputeShader(std::span<const uint32_t> spirv, const std::string& label) {
    if (spirv.size() < 5 || spirv[0] != 0x07230203u)
        throw Error(ErrorKind::InvalidArgument, "shader '" + label + "' is not SPIR-V (bad magic number or too short)");
    try {
        return Reflector(spirv, label).run();
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(ErrorKind::InvalidArgument, "shader '" + label + "': SPIR-V reflection failed: " + e.what());
    }
}

} // namespace hush::rhi
