#pragma once
// What compile() produces: the plan (cull, order, lifetimes, aliasing, barriers)
// and the physical resources, bind groups and barrier lists for both frame
// parities (history textures swap roles every frame).
#include <array>
#include <string>
#include <vector>

#include <hush/graph/compile_steps.hpp>
#include <hush/graph/pass_builder.hpp>
#include <hush/graph/render_graph.hpp>

namespace hush::graph {

struct BindGroupDecl {
    rhi::ComputePipeline pipeline;
    uint32_t set = 0;
    std::vector<GraphBinding> bindings;
};

struct RenderGraph::PassRuntime {
    ExecuteFn execute;
    std::vector<BindGroupDecl> bindGroups;
};

// The RHI barriers recorded before one pass, for one parity.
struct RecordedBarriers {
    std::vector<rhi::TextureBarrier> textures;
    std::vector<rhi::BufferBarrier> buffers;
    std::vector<rhi::MemoryBarrier> memory;
    bool empty() const { return textures.empty() && buffers.empty() && memory.empty(); }
};

struct CompiledGraph {
    CullResult cull;
    std::vector<uint32_t> order;
    std::vector<Lifetime> lifetimes;
    BarrierPlan barriers;
    rhi::Extent2D outputSize;
    std::vector<rhi::Extent2D> extents;           // by resource (textures)
    std::vector<bool> aliased;                    // by resource
    std::vector<uint64_t> memoryOffset;           // by resource: offset in the transient block, or kNone
    std::vector<uint32_t> aliasSlot;              // by resource
    std::vector<bool> historyPair;                // by resource: part of a ping-pong pair
    std::vector<rhi::TextureUsage> textureUsage;  // by resource
    rhi::MemoryBlock transientBlock;
    MemoryReport memory;

    // Physical resources by resource index and frame parity.
    std::vector<std::array<rhi::Texture, 2>> textures;
    std::vector<rhi::Buffer> buffers;
    // Bind groups by pass index, declaration index and parity.
    std::vector<std::vector<std::array<rhi::BindGroup, 2>>> bindGroups;
    std::vector<std::vector<uint32_t>> bindGroupSets;
    // Barriers by position in the order and parity; frame end by parity.
    std::vector<std::array<RecordedBarriers, 2>> passBarriers;
    std::array<RecordedBarriers, 2> frameEndBarriers;
};

} // namespace hush::graph
