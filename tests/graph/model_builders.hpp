#pragma once
// Hand-built GraphModels for the compile-step tests: models the builder could never
// produce (cycles, two writers of one version) and small ones whose expected results
// can be worked out on paper.
#include <string>
#include <vector>

#include <hush/graph/compile_steps.hpp>
#include <hush/graph/graph_model.hpp>

namespace hush::graph_test {

inline graph::ResourceDecl textureDecl(const std::string& name, graph::ResourceOrigin origin, uint32_t versions,
                                       rhi::Format format = rhi::Format::R32Uint,
                                       graph::SizeSpec size = graph::SizeSpec::absolute(32, 32)) {
    graph::ResourceDecl r;
    r.name = name;
    r.kind = graph::ResourceKind::Texture;
    r.origin = origin;
    r.texture = {format, size};
    r.versionCount = versions;
    if (origin == graph::ResourceOrigin::Imported) {
        r.initialState = rhi::ResourceState::StorageRead;
        r.finalState = rhi::ResourceState::StorageRead;
    }
    return r;
}

inline graph::AccessDecl accessDecl(const std::string& port, uint32_t resource, uint32_t version,
                                    graph::Access access) {
    graph::AccessDecl a;
    a.port = port;
    a.resource = resource;
    a.version = version;
    a.access = access;
    a.latestAtDeclaration = version;
    return a;
}

inline graph::AccessDecl readOf(uint32_t resource, uint32_t version, const std::string& port = "src") {
    return accessDecl(port, resource, version, graph::Access::StorageRead);
}
inline graph::AccessDecl writeOf(uint32_t resource, uint32_t version, const std::string& port = "dst") {
    return accessDecl(port, resource, version, graph::Access::StorageWrite);
}

inline graph::PassDecl passDecl(const std::string& name, std::vector<graph::AccessDecl> accesses,
                                bool sideEffect = false) {
    return {name, std::move(accesses), sideEffect};
}

inline graph::CullResult allAlive(const graph::GraphModel& model) {
    graph::CullResult c;
    c.passAlive.assign(model.passes.size(), true);
    c.resourceUsed.assign(model.resources.size(), true);
    return c;
}

} // namespace hush::graph_test
