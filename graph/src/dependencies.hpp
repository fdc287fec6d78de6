#pragma once
// Who produces and who reads each version of each resource, and the ordering edges
// that follow. Shared by validate, cull and order.
#include <vector>

#include <hush/graph/graph_model.hpp>

namespace hush::graph::detail {

struct Dependencies {
    // producers[r][v]: passes that write version v of resource r (more than one is an error)
    std::vector<std::vector<std::vector<uint32_t>>> producers;
    // readers[r][v]: passes that read version v of resource r
    std::vector<std::vector<std::vector<uint32_t>>> readers;
    // edges[p]: passes that must run after p
    std::vector<std::vector<uint32_t>> edges;

    explicit Dependencies(const GraphModel& model);
    static bool connected(const GraphModel& model, const AccessDecl& a);
};

} // namespace hush::graph::detail
