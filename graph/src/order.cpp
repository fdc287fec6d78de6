// Step 3: order. Kahn's algorithm over the live passes; among passes that are ready
// at the same time the one declared first runs first, so the order is stable.
#include <queue>

#include <hush/graph/compile_steps.hpp>
#include <hush/core/error.hpp>

#include "dependencies.hpp"

namespace hush::graph {

std::vector<uint32_t> order(const GraphModel& m, const CullResult& culled) {
    const detail::Dependencies deps(m);
    const size_t n = m.passes.size();
    std::vector<uint32_t> indegree(n, 0);
    for (uint32_t p = 0; p < n; ++p)
        if (culled.passAlive[p])
            for (uint32_t next : deps.edges[p])
                if (culled.passAlive[next]) ++indegree[next];

    std::priority_queue<uint32_t, std::vector<uint32_t>, std::greater<>> ready;
    for (uint32_t p = 0; p < n; ++p)
        if (culled.passAlive[p] && indegree[p] == 0) ready.push(p);
    std::vector<uint32_t> out;
    while (!ready.empty()) {
        const uint32_t p = ready.top();
        ready.pop();
        out.push_back(p);
        for (uint32_t next : deps.edges[p])
            if (culled.passAlive[next] && --indegree[next] == 0) ready.push(next);
    }

    size_t alive = 0;
    for (bool a : culled.passAlive) alive += a;
    if (out.size() != alive) {
        std::string stuck;
        for (uint32_t p = 0; p < n; ++p)
            if (culled.passAlive[p] && indegree[p] > 0) stuck += (stuck.empty() ? "'" : ", '") + m.passes[p].name + "'";
        throw Error(ErrorKind::InvalidArgument, "render graph has a cycle: passes " + stuck +
                                                    " each wait for another of them");
    }
    return out;
}

} // namespace hush::graph
