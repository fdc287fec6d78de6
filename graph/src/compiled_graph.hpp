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

// The RHI barriers recorded before one pass, for one parity.
struct RecordedBarriers {
    std::vector<rhi::TextureBarrier> textures;
    std::vector<rhi::BufferBarrier> buffers;
    std::vector<rhi::MemoryBarrier> memory;
    bool empty() const { return textures.empty() && buffers.empty() && memory.empty(); }
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

    // Bind groups by pass index, declaration index and parity.
    std::vector<std::vector<std::array<rhi::BindGroup, 2>>> bindGroups;
    std::vector<std::vector<uint32_t>> bindGroupSets;
    // Barriers by position in the order and parity; frame end by parity.
    std::vector<std::array<RecordedBarriers, 2>> passBarriers;
    std::array<RecordedBarriers, 2> frameEndBarriers;
};

// Makes every live pass's bind groups for both parities: each shader binding is bound
// to the pass's port of the same name (or a fixed binding), checked against the
// pipeline's reflected layout; errors name the pass, the binding and the ports.
void createBindGroups(const rhi::Device& device, const GraphModel& model,
                      const std::vector<std::vector<BindGroupDecl>>& declared, CompiledGraph& compiled);

} // namespace hush::graph
