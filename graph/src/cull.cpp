// Step 2: cull. Start from what the outside sees (outputs, imported resources a pass
// writes, side-effect passes, the history next frame reads) and keep only passes
// that contribute to it. This is how a chain runs only what a scene needs.
#include <hush/graph/compile_steps.hpp>

#include "dependencies.hpp"

namespace hush::graph {

CullResult cull(const GraphModel& m) {
    const detail::Dependencies deps(m);
    CullResult out;
    out.passAlive.assign(m.passes.size(), false);
    out.resourceUsed.assign(m.resources.size(), false);
    std::vector<uint32_t> work;
    auto keep = [&](uint32_t p) {
        if (!out.passAlive[p]) {
            out.passAlive[p] = true;
            work.push_back(p);
        }
    };
    auto keepProducersOf = [&](uint32_t r, uint32_t v) {
        if (r < deps.producers.size() && v < deps.producers[r].size())
            for (uint32_t p : deps.producers[r][v]) keep(p);
    };
    auto finalVersion = [&](uint32_t r) { return m.resources[r].versionCount - 1; };

    for (uint32_t p = 0; p < m.passes.size(); ++p) {
        if (m.passes[p].sideEffect) keep(p);
        for (const auto& a : m.passes[p].accesses)
            if (detail::Dependencies::connected(m, a) && isWrite(a.access) &&
                m.resources[a.resource].origin == ResourceOrigin::Imported)
                keep(p);   // writing the application's resource is visible outside the graph
    }
    for (uint32_t r = 0; r < m.resources.size(); ++r)
        if (m.resources[r].output) keepProducersOf(r, finalVersion(r));

    while (!work.empty()) {
        const uint32_t p = work.back();
        work.pop_back();
        for (const auto& a : m.passes[p].accesses) {
            if (!detail::Dependencies::connected(m, a)) continue;
            if (isRead(a.access)) keepProducersOf(a.resource, a.version);
            // A live reader of last frame's value needs this frame's final value made.
            if (m.resources[a.resource].origin == ResourceOrigin::History) {
                const uint32_t source = m.historySource(a.resource);
                if (source != kNone) keepProducersOf(source, finalVersion(source));
            }
        }
    }

    for (uint32_t p = 0; p < m.passes.size(); ++p) {
        if (!out.passAlive[p]) {
            out.culled.push_back(p);
            continue;
        }
        for (const auto& a : m.passes[p].accesses)
            if (detail::Dependencies::connected(m, a)) out.resourceUsed[a.resource] = true;
    }
    return out;
}

} // namespace hush::graph
