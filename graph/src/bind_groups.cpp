// Bind groups, made once per compile for both frame parities. A pass's ports and its
// shader's bindings meet here, by name: one name from the pass to the shader.
#include <algorithm>

#include <hush/core/error.hpp>

#include "compiled_graph.hpp"

namespace hush::graph {

namespace {

bool isCopy(Access a) { return a == Access::CopySrc || a == Access::CopyDst; }

// The pass's access whose port is `name` (the last one: a port read and then written
// names one resource).
const AccessDecl* findPort(const PassDecl& pass, std::string_view name) {
    const AccessDecl* found = nullptr;
    for (const auto& a : pass.accesses)
        if (a.port == name) found = &a;
    return found;
}

std::string portList(const PassDecl& pass) {
    std::string list;
    for (const auto& a : pass.accesses)
        if (!isCopy(a.access) && list.find("'" + a.port + "'") == std::string::npos)
            list += (list.empty() ? "'" : ", '") + a.port + "'";
    return list.empty() ? "none" : list;
}

// A 1x1 texture for an optional port left unconnected, in the state its binding
// needs (made once per compile and kind/format).
const rhi::Texture& placeholderFor(const rhi::Device& device, const rhi::BindGroupLayoutEntry& entry,
                                   CompiledGraph& c, std::vector<rhi::TextureBarrier>& setup) {
    const bool storage = entry.kind == rhi::BindingKind::StorageTexture;
    const rhi::Format format = storage ? entry.storageFormat : rhi::Format::RGBA32Float;
    for (const auto& t : c.placeholders)
        if (t.format() == format && bool(t.usage() & rhi::TextureUsage::StorageBinding) == storage) return t;
    c.placeholders.push_back(device.createTexture(
        {.label = std::string("placeholder.") + std::string(rhi::toString(format)), .size = {1, 1}, .format = format,
         .usage = storage ? rhi::TextureUsage::StorageBinding : rhi::TextureUsage::TextureBinding}));
    setup.push_back({c.placeholders.back(), rhi::ResourceState::Undefined,
                     storage ? rhi::ResourceState::General : rhi::ResourceState::SampledRead});
    return c.placeholders.back();
}

struct GroupContext {
    const rhi::Device& device;
    const GraphModel& model;
    CompiledGraph& c;
    std::vector<rhi::TextureBarrier>& setup;
};

rhi::BindGroupEntry entryFor(GroupContext& g, const PassDecl& pass, const BindGroupDecl& decl,
                             const rhi::BindGroupLayoutEntry& binding, uint32_t parity) {
    rhi::BindGroupEntry e{.binding = binding.binding, .name = binding.name};
    if (const AccessDecl* port = findPort(pass, binding.name)) {
        if (port->resource == kNone) {
            if (binding.kind != rhi::BindingKind::SampledTexture && binding.kind != rhi::BindingKind::StorageTexture)
                throw Error(ErrorKind::InvalidArgument, "pass '" + pass.name + "': optional port '" + port->port +
                                                            "' is unconnected, but only texture ports may be");
            e.texture = placeholderFor(g.device, binding, g.c, g.setup);
        } else if (g.model.resources[port->resource].kind == ResourceKind::Texture) {
            e.texture = g.c.textures[port->resource][parity];
        } else {
            e.buffer = g.c.buffers[port->resource];
        }
        return e;
    }
    const auto fixed = std::find_if(decl.fixed.begin(), decl.fixed.end(),
                                    [&](const FixedBinding& f) { return f.name == binding.name; });
    if (fixed == decl.fixed.end())
        throw Error(ErrorKind::BindingMismatch,
                    "pass '" + pass.name + "': binding '" + binding.name + "' (set " + std::to_string(decl.set) +
                        ", binding " + std::to_string(binding.binding) + ") of shader '" + decl.pipeline.label() +
                        "' has no port of that name; the pass's ports: " + portList(pass));
    e.buffer = fixed->buffer;
    e.sampler = fixed->sampler;
    return e;
}

// Every port a shader reads or writes must be bound: a misspelt port is an error, not
// a resource silently never bound.
void requireEveryPortBound(const PassDecl& pass, const std::vector<BindGroupDecl>& decls) {
    for (const auto& a : pass.accesses) {
        if (isCopy(a.access) || a.resource == kNone) continue;   // an unconnected port binds nothing
        bool bound = false;
        for (const auto& d : decls)
            bound = bound || d.pipeline.getBindGroupLayout(d.set).findName(a.port) != nullptr;
        if (!bound)
            throw Error(ErrorKind::BindingMismatch, "pass '" + pass.name + "': port '" + a.port +
                                                        "' is bound to no binding of its shader '" +
                                                        decls.front().pipeline.label() + "' (misspelt?)");
    }
}

} // namespace

void createBindGroups(const rhi::Device& device, const GraphModel& model,
                      const std::vector<std::vector<BindGroupDecl>>& declared, CompiledGraph& c) {
    std::vector<rhi::TextureBarrier> setup;
    GroupContext g{device, model, c, setup};
    c.bindGroups.clear();
    c.bindGroupRanges.assign(model.passes.size(), {});
    for (uint32_t p : c.order) {
        const auto& pass = model.passes[p];
        if (!declared[p].empty()) requireEveryPortBound(pass, declared[p]);
        c.bindGroupRanges[p] = {.first = uint32_t(c.bindGroups.size()), .count = uint32_t(declared[p].size())};
        for (const auto& decl : declared[p]) {
            const auto layout = decl.pipeline.getBindGroupLayout(decl.set);
            std::array<rhi::BindGroup, 2> groups;
            for (uint32_t parity = 0; parity < 2; ++parity) {
                rhi::BindGroupDesc bg{.label = pass.name + ".set" + std::to_string(decl.set), .layout = layout,
                                      .entries = {}};
                for (const auto& binding : layout.entries()) bg.entries.push_back(entryFor(g, pass, decl, binding, parity));
                try {
                    groups[parity] = device.createBindGroup(bg);
                } catch (const Error& e) {
                    throw Error(e.kind(), "pass '" + pass.name + "': " + e.what());
                }
            }
            c.bindGroups.push_back({.groups = groups, .set = decl.set});
        }
    }
    if (setup.empty()) return;
    auto encoder = device.createCommandEncoder({.label = "placeholders.setup"});
    encoder.barrier(setup);
    auto queue = device.queue();
    queue.wait(queue.submit(encoder.finish()));
}

} // namespace hush::graph
