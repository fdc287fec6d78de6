// RenderGraph: declaration and introspection. Compiling lives in graph_compile.cpp,
// executing in graph_execute.cpp, dumping in graph_dump.cpp.
#include <hush/graph/render_graph.hpp>
#include <hush/core/error.hpp>

#include "compiled_graph.hpp"
#include "frame_slot.hpp"

namespace hush::graph {

RenderGraph::RenderGraph(rhi::Device device, const RenderGraphDesc& desc) : device_(std::move(device)), desc_(desc) {
    if (!device_) throw Error(ErrorKind::InvalidArgument, "render graph '" + desc.label + "' needs a device");
    if (desc_.framesInFlight == 0) desc_.framesInFlight = 1;
}

RenderGraph::~RenderGraph() {
    try {
        waitIdle();
    } catch (...) {
        // A lost device cannot be waited for; destruction must go on regardless.
    }
}

uint32_t RenderGraph::addResource(ResourceDecl decl) {
    model_.resources.push_back(std::move(decl));
    importedTextures_.emplace_back();
    importedBuffers_.emplace_back();
    markDirty();
    return uint32_t(model_.resources.size() - 1);
}

PassId RenderGraph::addPass(const std::string& name, const SetupFn& setup) {
    const PassId id = PassId(model_.passes.size());
    model_.passes.push_back({name, {}, false});
    passes_.emplace_back();
    markDirty();
    PassBuilder builder(*this, id);
    passes_[id].execute = setup(builder);
    if (!passes_[id].execute)
        throw Error(ErrorKind::InvalidArgument, "the setup of pass '" + name + "' returned no execute function");
    return id;
}

TextureHandle RenderGraph::importTexture(const std::string& name, const rhi::Texture& texture, const ImportDesc& desc) {
    if (!texture) throw Error(ErrorKind::InvalidArgument, "importTexture '" + name + "': empty texture");
    ResourceDecl decl;
    decl.name = name;
    decl.kind = ResourceKind::Texture;
    decl.origin = ResourceOrigin::Imported;
    decl.texture = {texture.format(), SizeSpec::absolute(texture.width(), texture.height())};
    decl.initialState = desc.initialState;
    decl.finalState = desc.finalState;
    const uint32_t index = addResource(std::move(decl));
    importedTextures_[index] = texture;
    return {index, 0};
}

BufferHandle RenderGraph::importBuffer(const std::string& name, const rhi::Buffer& buffer, const ImportDesc& desc) {
    if (!buffer) throw Error(ErrorKind::InvalidArgument, "importBuffer '" + name + "': empty buffer");
    ResourceDecl decl;
    decl.name = name;
    decl.kind = ResourceKind::Buffer;
    decl.origin = ResourceOrigin::Imported;
    decl.buffer = {buffer.size()};
    decl.initialState = desc.initialState;
    decl.finalState = desc.finalState;
    const uint32_t index = addResource(std::move(decl));
    importedBuffers_[index] = buffer;
    return {index, 0};
}

TextureHandle RenderGraph::history(const std::string& name, const TextureInfo& info) {
    ResourceDecl decl;
    decl.name = name;
    decl.kind = ResourceKind::Texture;
    decl.origin = ResourceOrigin::History;
    decl.texture = info;
    return {addResource(std::move(decl)), 0};
}

TextureHandle RenderGraph::history(TextureHandle source) {
    checkTransient(source, "history");
    for (uint32_t r = 0; r < model_.resources.size(); ++r)
        if (model_.resources[r].origin == ResourceOrigin::History && model_.resources[r].historySource == source.index)
            return {r, 0};
    const auto& src = model_.resources[source.index];
    const TextureHandle h = history(src.name, src.texture);
    model_.resources[h.index].historySource = source.index;
    return h;
}

void RenderGraph::bindHistory(TextureHandle history, TextureHandle source) {
    checkTransient(source, "bindHistory");
    if (history.index >= model_.resources.size() || model_.resources[history.index].origin != ResourceOrigin::History)
        throw Error(ErrorKind::InvalidArgument, "bindHistory: the first handle is not a history of graph '" +
                                                    desc_.label + "'");
    auto& h = model_.resources[history.index];
    for (const auto& other : model_.resources)
        if (&other != &h && other.origin == ResourceOrigin::History && other.historySource == source.index)
            throw Error(ErrorKind::InvalidArgument, "bindHistory: '" + model_.resources[source.index].name +
                                                        "' already has a history ('" + other.name +
                                                        "'); read that one");
    if (h.historySource != kNone && h.historySource != source.index)
        throw Error(ErrorKind::InvalidArgument, "bindHistory: history '" + h.name + "' is already bound to '" +
                                                    model_.resources[h.historySource].name + "'");
    h.historySource = source.index;
    markDirty();
}

void RenderGraph::checkTransient(TextureHandle texture, const char* call) const {
    if (texture.index >= model_.resources.size() ||
        model_.resources[texture.index].origin != ResourceOrigin::Transient ||
        model_.resources[texture.index].kind != ResourceKind::Texture)
        throw Error(ErrorKind::InvalidArgument, std::string(call) + ": the source must be a texture a pass of graph '" +
                                                    desc_.label + "' creates");
}

TextureHandle RenderGraph::findTexture(std::string_view name) const {
    for (uint32_t r = 0; r < model_.resources.size(); ++r) {
        const auto& res = model_.resources[r];
        if (res.name == name && res.kind == ResourceKind::Texture && res.origin != ResourceOrigin::History)
            return {r, res.versionCount - 1};
    }
    return {};
}

BufferHandle RenderGraph::findBuffer(std::string_view name) const {
    for (uint32_t r = 0; r < model_.resources.size(); ++r) {
        const auto& res = model_.resources[r];
        if (res.name == name && res.kind == ResourceKind::Buffer) return {r, res.versionCount - 1};
    }
    return {};
}

TextureHandle RenderGraph::historySource(TextureHandle history) const {
    const uint32_t s = model_.historySource(history.index);
    if (s == kNone) return {};
    return {s, model_.resources[s].versionCount - 1};
}

void RenderGraph::markOutput(TextureHandle texture) {
    if (texture.index >= model_.resources.size())
        throw Error(ErrorKind::InvalidArgument, "markOutput: the texture handle does not belong to this graph");
    if (model_.resources[texture.index].output) return;   // nothing changes: no recompile
    model_.resources[texture.index].output = true;
    markDirty();
}

void RenderGraph::markOutput(BufferHandle buffer) {
    if (buffer.index >= model_.resources.size())
        throw Error(ErrorKind::InvalidArgument, "markOutput: the buffer handle does not belong to this graph");
    if (model_.resources[buffer.index].output) return;
    model_.resources[buffer.index].output = true;
    markDirty();
}

void RenderGraph::setOutputSize(rhi::Extent2D size) {
    if (size.width == 0 || size.height == 0)
        throw Error(ErrorKind::InvalidArgument, "render graph '" + desc_.label + "': output size must be at least 1x1");
    if (size == model_.outputSize) return;
    model_.outputSize = size;
    markDirty();
}

rhi::Extent2D RenderGraph::outputSize() const { return model_.outputSize; }

void RenderGraph::resetHistory() {
    historyValid_ = false;
    framesSinceHistoryReset_ = 0;
}

bool RenderGraph::needsCompile() const { return dirty_ || !compiled_; }

const CompiledGraph& RenderGraph::compiled() const {
    if (!compiled_)
        throw Error(ErrorKind::InvalidArgument, "render graph '" + desc_.label + "' has not been compiled yet");
    return *compiled_;
}

const rhi::Texture& RenderGraph::outputTexture(TextureHandle texture) const {
    const auto& c = compiled();
    if (texture.index >= c.textures.size() || !c.textures[texture.index][0])
        throw Error(ErrorKind::InvalidArgument, "outputTexture: the handle names no texture of the compiled graph "
                                                "(was it culled? mark it as an output)");
    // The texture written in the frame just executed (history sources alternate).
    const uint64_t lastParity = (frame_ - compiledAtFrame_ + 1) % 2;
    return c.textures[texture.index][c.historyPair[texture.index] ? lastParity : 0];
}

const rhi::Buffer& RenderGraph::outputBuffer(BufferHandle buffer) const {
    const auto& c = compiled();
    if (buffer.index >= c.buffers.size() || !c.buffers[buffer.index])
        throw Error(ErrorKind::InvalidArgument, "outputBuffer: the handle names no buffer of the compiled graph");
    return c.buffers[buffer.index];
}

rhi::ResourceState RenderGraph::outputState(TextureHandle texture) const {
    const auto& c = compiled();
    if (texture.index >= c.barriers.endState.size())
        throw Error(ErrorKind::InvalidArgument, "outputState: the handle names no resource of the compiled graph");
    return c.barriers.endState[texture.index];
}

MemoryReport RenderGraph::memory() const { return compiled().memory; }

std::vector<std::string> RenderGraph::culledPasses() const {
    std::vector<std::string> out;
    for (uint32_t p : compiled().cull.culled) out.push_back(model_.passes[p].name);
    return out;
}

std::vector<std::string> RenderGraph::passOrder() const {
    std::vector<std::string> out;
    for (uint32_t p : compiled().order) out.push_back(model_.passes[p].name);
    return out;
}

size_t RenderGraph::barrierCount() const { return compiled().barriers.count(); }

} // namespace hush::graph
