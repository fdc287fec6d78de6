#include <hush/graph/pass_builder.hpp>
#include <hush/graph/render_graph.hpp>

#include "compiled_graph.hpp"

namespace hush::graph {

namespace {

template <class Handle>
AccessDecl makeAccess(const GraphModel& m, const std::string& port, Handle h, Access access, const InputSpec& spec) {
    AccessDecl a;
    a.port = port;
    a.access = access;
    a.optional = spec.optional;
    a.expectFormat = spec.format;
    a.expectSize = spec.size;
    if (h.valid()) {
        a.resource = h.index;
        a.version = h.version;
        if (h.index < m.resources.size()) a.latestAtDeclaration = m.resources[h.index].versionCount - 1;
    }
    return a;
}

} // namespace

TextureHandle PassBuilder::create(const std::string& name, const TextureInfo& info) {
    ResourceDecl decl;
    decl.name = name;
    decl.kind = ResourceKind::Texture;
    decl.texture = info;
    return {graph_.addResource(std::move(decl)), 0};
}

BufferHandle PassBuilder::create(const std::string& name, const BufferInfo& info) {
    ResourceDecl decl;
    decl.name = name;
    decl.kind = ResourceKind::Buffer;
    decl.buffer = info;
    return {graph_.addResource(std::move(decl)), 0};
}

TextureHandle PassBuilder::read(const std::string& port, TextureHandle h, const InputSpec& spec) {
    return addRead(port, h, Access::StorageRead, spec);
}
TextureHandle PassBuilder::sample(const std::string& port, TextureHandle h, const InputSpec& spec) {
    return addRead(port, h, Access::SampledRead, spec);
}
BufferHandle PassBuilder::read(const std::string& port, BufferHandle h, const InputSpec& spec) {
    return addRead(port, h, Access::StorageRead, spec);
}
BufferHandle PassBuilder::readUniform(const std::string& port, BufferHandle h, const InputSpec& spec) {
    return addRead(port, h, Access::UniformRead, spec);
}
BufferHandle PassBuilder::readIndirect(const std::string& port, BufferHandle h, const InputSpec& spec) {
    return addRead(port, h, Access::IndirectRead, spec);
}

template <class Handle>
Handle PassBuilder::addRead(const std::string& port, Handle h, Access access, const InputSpec& spec) {
    graph_.model_.passes[pass_].accesses.push_back(makeAccess(graph_.model_, port, h, access, spec));
    graph_.markDirty();
    return h;
}

namespace {

// Records a write and hands back the version it produces.
template <class Handle>
Handle recordWrite(GraphModel& m, uint32_t pass, const std::string& port, Handle h, Access access) {
    m.passes[pass].accesses.push_back(makeAccess(m, port, h, access, {}));
    if (!h.valid() || h.index >= m.resources.size()) return h;   // validate() reports it
    auto& res = m.resources[h.index];
    ++res.versionCount;
    return {h.index, res.versionCount - 1};
}

} // namespace

TextureHandle PassBuilder::write(const std::string& port, TextureHandle h) {
    graph_.markDirty();
    return recordWrite(graph_.model_, pass_, port, h, Access::StorageWrite);
}
TextureHandle PassBuilder::readWrite(const std::string& port, TextureHandle h) {
    graph_.markDirty();
    return recordWrite(graph_.model_, pass_, port, h, Access::StorageReadWrite);
}
BufferHandle PassBuilder::write(const std::string& port, BufferHandle h) {
    graph_.markDirty();
    return recordWrite(graph_.model_, pass_, port, h, Access::StorageWrite);
}
BufferHandle PassBuilder::readWrite(const std::string& port, BufferHandle h) {
    graph_.markDirty();
    return recordWrite(graph_.model_, pass_, port, h, Access::StorageReadWrite);
}
TextureHandle PassBuilder::copyFrom(const std::string& port, TextureHandle h) {
    graph_.model_.passes[pass_].accesses.push_back(makeAccess(graph_.model_, port, h, Access::CopySrc, {}));
    graph_.markDirty();
    return h;
}
TextureHandle PassBuilder::copyTo(const std::string& port, TextureHandle h) {
    graph_.markDirty();
    return recordWrite(graph_.model_, pass_, port, h, Access::CopyDst);
}

BindGroupHandle PassBuilder::bindGroup(const rhi::ComputePipeline& pipeline, uint32_t set,
                                       std::vector<FixedBinding> fixed) {
    auto& decls = graph_.passes_[pass_].bindGroups;
    decls.push_back({pipeline, set, std::move(fixed)});
    graph_.markDirty();
    return {pass_, uint32_t(decls.size() - 1)};
}

void PassBuilder::sideEffect() {
    graph_.model_.passes[pass_].sideEffect = true;
    graph_.markDirty();
}

} // namespace hush::graph
