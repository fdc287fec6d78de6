#pragma once
// The compile pipeline, one function per step, each usable and testable alone:
//   validate -> cull -> order -> lifetimes + aliasing -> barriers
// RenderGraph::compile runs them in that order; the record step lives in the executor.
#include <cstdint>
#include <string>
#include <vector>

#include <hush/graph/graph_model.hpp>
#include <hush/rhi/resource_state.hpp>

namespace hush::graph {

// 1. Throws hush::Error listing every problem, one per line, each naming the pass,
//    the port and the resource: unknown or stale handles, unconnected required
//    inputs, reads of versions nobody writes, format / extent mismatches, two
//    unordered writers of one version, history without a source, cycles.
void validate(const GraphModel& model);

// 2. Passes that reach no output, history or side effect are dropped.
struct CullResult {
    std::vector<bool> passAlive;       // by pass index
    std::vector<bool> resourceUsed;    // by resource index: touched by a live pass
    std::vector<uint32_t> culled;      // pass indices, in declaration order
};
CullResult cull(const GraphModel& model);

// 3. Live passes in dependency order (read-after-write, write-after-read,
//    write-after-write), ties broken by declaration order. Throws on a cycle.
std::vector<uint32_t> order(const GraphModel& model, const CullResult& culled);

// 4a. First and last position (in the order) at which each resource is used.
struct Lifetime {
    uint32_t first = kNone;   // kNone: unused
    uint32_t last = 0;
    bool used() const { return first != kNone; }
};
std::vector<Lifetime> lifetimes(const GraphModel& model, const std::vector<uint32_t>& passOrder);

// 4b. Memory aliasing: place items in one block so that items whose lifetimes
//     overlap never overlap in memory. Greedy, largest first, lowest fitting offset.
struct AliasItem {
    uint64_t size = 0;
    uint64_t alignment = 1;
    Lifetime lifetime;
};
struct AliasPlan {
    std::vector<uint64_t> offsets;    // by item
    std::vector<uint32_t> slots;      // items with the same slot start at the same offset
    uint64_t blockBytes = 0;          // peak with aliasing
    uint64_t unaliasedBytes = 0;      // what separate allocations would take
};
AliasPlan planAliasing(const std::vector<AliasItem>& items);

// 5. Barriers, computed once. A hazard (any write, or a change of image layout)
//    gets a barrier; two reads in the same layout get none.
struct PlannedBarrier {
    uint32_t resource = kNone;
    rhi::ResourceState before = rhi::ResourceState::Undefined;
    rhi::ResourceState after = rhi::ResourceState::Undefined;
    bool discard = false;        // contents are not needed (first write of a frame)
    bool aliased = false;        // the memory held another resource before: add a memory barrier
    bool historyPhysical = false;   // applies to the history's physical texture of this frame
};
struct BarrierPlan {
    std::vector<std::vector<PlannedBarrier>> beforePass;   // by position in the order
    std::vector<PlannedBarrier> frameEnd;                  // imported resources to their final states
    // The state each resource is left in at the end of a frame (next frame starts there).
    std::vector<rhi::ResourceState> endState;
    size_t count() const;
};
// `aliased[r]` says whether transient r shares memory with another resource.
BarrierPlan planBarriers(const GraphModel& model, const std::vector<uint32_t>& passOrder,
                         const std::vector<bool>& aliased);

} // namespace hush::graph
