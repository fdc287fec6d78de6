#pragma once
// PassBuilder: what a pass's setup step uses to declare its ports. Each read or
// write names a port ("color", "motion"), so errors can say which input of which
// pass is wrong, as Falcor's render passes do.
#include <optional>
#include <string>
#include <vector>

#include <hush/graph/graph_model.hpp>
#include <hush/graph/handles.hpp>
#include <hush/rhi/bind_group.hpp>
#include <hush/rhi/buffer.hpp>
#include <hush/rhi/pipeline.hpp>
#include <hush/rhi/texture.hpp>

namespace hush::graph {

class RenderGraph;

// What a read may require of the resource connected to it.
struct InputSpec {
    bool optional = false;                     // may be left unconnected (an invalid handle)
    std::optional<rhi::Format> format;         // checked at compile time
    std::optional<SizeSpec> size;
};

// A resource the graph does not manage, bound to the shader variable called `name`:
// a buffer of constants, a sampler.
struct FixedBinding {
    std::string name;
    rhi::Buffer buffer;
    rhi::Sampler sampler;
};

class PassBuilder {
public:
    // A transient texture or buffer, created by this pass (version 0: no contents
    // yet, so write it before anything reads it).
    TextureHandle create(const std::string& name, const TextureInfo& info);
    BufferHandle create(const std::string& name, const BufferInfo& info);

    // Reads. The returned handle is the same version (reads do not version).
    TextureHandle read(const std::string& port, TextureHandle texture, const InputSpec& spec = {});
    TextureHandle sample(const std::string& port, TextureHandle texture, const InputSpec& spec = {});
    BufferHandle read(const std::string& port, BufferHandle buffer, const InputSpec& spec = {});
    BufferHandle readUniform(const std::string& port, BufferHandle buffer, const InputSpec& spec = {});
    // A buffer whose first 12 bytes are this pass's workgroup counts
    // (PassContext::dispatchIndirect), also bound read-only to the shader's buffer of
    // the port's name.
    BufferHandle readIndirect(const std::string& port, BufferHandle buffer, const InputSpec& spec = {});

    // Writes return the next version; use it for every later access.
    TextureHandle write(const std::string& port, TextureHandle texture);
    TextureHandle readWrite(const std::string& port, TextureHandle texture);
    BufferHandle write(const std::string& port, BufferHandle buffer);
    BufferHandle readWrite(const std::string& port, BufferHandle buffer);
    TextureHandle copyFrom(const std::string& port, TextureHandle texture);   // copy source
    TextureHandle copyTo(const std::string& port, TextureHandle texture);     // copy destination (writes)

    // A bind group for `pipeline`'s set `set`, bound by name at compile time: each of
    // the shader's bindings takes this pass's port of the same name (one spelling from
    // the pass to the shader), or the fixed binding of that name. An optional input
    // left unconnected binds a 1x1 placeholder, which the shader must not read (say so
    // in its push constants). A shader binding with no such port, or a port no shader
    // binding takes, is an error naming both sides.
    BindGroupHandle bindGroup(const rhi::ComputePipeline& pipeline, uint32_t set = 0, std::vector<FixedBinding> fixed = {});

    // Keep this pass even if nothing reads its results (it writes to the outside).
    void sideEffect();

private:
    friend class RenderGraph;
    PassBuilder(RenderGraph& graph, uint32_t pass) : graph_(graph), pass_(pass) {}
    template <class Handle>
    Handle addRead(const std::string& port, Handle h, Access access, const InputSpec& spec);
    RenderGraph& graph_;
    uint32_t pass_;
};

} // namespace hush::graph
