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
    std::vector<FixedBinding> fixed;
};

struct RenderGraph::PassRuntime {
    ExecuteFn execute;
    std::vector<BindGroupDecl> bindGroups;
};

// One bind group a live pass declared, for both parities, and the set it binds at.
struct PassBindGroup {
    std::array<rhi::BindGroup, 2> groups;
    uint32_t set = 0;
};

// Where one pass's bind groups lie in CompiledGraph::bindGroups.
struct BindGroupRange {
    uint32_t first = 0;
    uint32_t count = 0;
};

// Where one step's barriers lie in its parity's lists: [first, first + count) of each.
struct BarrierRange {
    uint32_t firstTexture = 0, textureCount = 0;
    uint32_t firstBuffer = 0, bufferCount = 0;
    uint32_t firstMemory = 0, memoryCount = 0;
    bool empty() const { return textureCount == 0 && bufferCount == 0 && memoryCount == 0; }
};

// Every step's RHI barriers for one parity, back to back in recording order; the
// steps are the passes by position in the order, then the frame end.
struct BarrierLists {
    std::vector<rhi::TextureBarrier> textures;
    std::vector<rhi::BufferBarrier> buffers;
    std::vector<rhi::MemoryBarrier> memory;
    std::vector<BarrierRange> steps;
};

struct CompiledGraph : RealizedResources {
    CullResult cull;
    std::vector<uint32_t> order;
    std::vector<Lifetime> lifetimes;
    BarrierPlan barriers;
    rhi::Extent2D outputSize;
    // What an optional port left unconnected binds (1x1, never read): one per binding
    // kind and format, made only when needed.
    std::vector<rhi::Texture> placeholders;

    // What a frame reads while it records lies in a few flat arrays, in recording
    // order: after lavapipe's shader threads have run a 1280x720 frame on the same
    // cores, little of it is still cached, and with a vector per pass every pass cost
    // several cache misses (hush-bench-graph, docs/benchmarks.md "Render graph").
    // Bind groups: pass p's declaration d is bindGroups[bindGroupRanges[p].first + d].
    std::vector<PassBindGroup> bindGroups;
    std::vector<BindGroupRange> bindGroupRanges;   // by pass index
    std::array<BarrierLists, 2> barrierLists;      // by parity
};

// Makes every live pass's bind groups for both parities: each shader binding is bound
// to the pass's port of the same name (or a fixed binding), checked against the
// pipeline's reflected layout; errors name the pass, the binding and the ports.
void createBindGroups(const rhi::Device& device, const GraphModel& model,
                      const std::vector<std::vector<BindGroupDecl>>& declared, CompiledGraph& compiled);

} // namespace hush::graph
