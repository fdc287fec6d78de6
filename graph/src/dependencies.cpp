#include "dependencies.hpp"

#include <algorithm>

namespace hush::graph::detail {

bool Dependencies::connected(const GraphModel& model, const AccessDecl& a) {
    return a.resource < model.resources.size() && a.version < model.resources[a.resource].versionCount;
}

Dependencies::Dependencies(const GraphModel& model) {
    const size_t n = model.resources.size();
    producers.resize(n);
    readers.resize(n);
    for (size_t r = 0; r < n; ++r) {
        producers[r].resize(model.resources[r].versionCount + 1);
        readers[r].resize(model.resources[r].versionCount + 1);
    }
    for (uint32_t p = 0; p < model.passes.size(); ++p) {
        for (const auto& a : model.passes[p].accesses) {
            if (!connected(model, a)) continue;
            if (isRead(a.access)) readers[a.resource][a.version].push_back(p);
            if (isWrite(a.access)) producers[a.resource][a.version + 1].push_back(p);
        }
    }
    edges.resize(model.passes.size());
    auto edge = [&](uint32_t from, uint32_t to) {
        if (from != to) edges[from].push_back(to);
    };
    for (uint32_t p = 0; p < model.passes.size(); ++p) {
        for (const auto& a : model.passes[p].accesses) {
            if (!connected(model, a)) continue;
            for (uint32_t producer : producers[a.resource][a.version]) edge(producer, p);      // RAW, WAW
            if (isWrite(a.access))
                for (uint32_t reader : readers[a.resource][a.version]) edge(reader, p);       // WAR
        }
    }
    for (auto& e : edges) {
        std::sort(e.begin(), e.end());
        e.erase(std::unique(e.begin(), e.end()), e.end());
    }
}

} // namespace hush::graph::detail
