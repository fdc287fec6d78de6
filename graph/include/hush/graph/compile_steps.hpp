#pragma once
// The compile pipeline, one function per step, each usable and testable alone:
//   validate -> cull -> order -> lifetimes + aliasing -> barriers -> realize
// RenderGraph::compile runs them in that order (then makes the bind groups and the
// RHI barrier lists); the record step lives in the executor.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <hush/graph/graph_model.hpp>
#include <hush/rhi/buffer.hpp>
#include <hush/rhi/device.hpp>
#include <hush/rhi/memory_block.hpp>
#include <hush/rhi/resource_state.hpp>
#include <hush/rhi/texture.hpp>

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

struct MemoryReport {
    uint64_t transientAliasedBytes = 0;     // the one memory block all transients share
    uint64_t transientUnaliasedBytes = 0;   // what they would take, each in its own memory
    uint64_t historyBytes = 0;              // both halves of every history ping-pong pair
    uint64_t outputBytes = 0;               // transients marked as outputs (never aliased)
    uint32_t transientTextures = 0;
};

// 6. Realize: the physical resources of a planned graph, on `device`. Transient
//    textures share one memory block where their lifetimes allow (planAliasing); a
//    history and its source share a ping-pong pair (the two textures swap roles every
//    frame: index [parity]); imported resources are the application's own.
struct RealizeOptions {
    std::string label;                              // names the memory block
    bool aliasing = true;
    std::vector<rhi::Texture> importedTextures;     // by resource index (empty when not imported)
    std::vector<rhi::Buffer> importedBuffers;
};
struct RealizedResources {
    std::vector<rhi::Extent2D> extents;             // by resource (textures)
    std::vector<bool> aliased;                      // shares memory with another resource
    std::vector<uint64_t> memoryOffset;             // offset in the transient block, or kNone
    std::vector<uint32_t> aliasSlot;                // resources with the same slot start at the same offset
    std::vector<bool> historyPair;                  // part of a ping-pong pair
    std::vector<rhi::TextureUsage> textureUsage;
    std::vector<std::array<rhi::Texture, 2>> textures;   // by resource and frame parity
    std::vector<rhi::Buffer> buffers;
    rhi::MemoryBlock transientBlock;
    MemoryReport memory;
};
RealizedResources realize(const rhi::Device& device, const GraphModel& model, const CullResult& culled,
                          const std::vector<uint32_t>& passOrder, const std::vector<Lifetime>& lifetimes,
                          const RealizeOptions& options);

} // namespace hush::graph
