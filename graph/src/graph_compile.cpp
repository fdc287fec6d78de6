// RenderGraph::compile: the steps of compile_steps.hpp (validate, cull, order,
// lifetimes, realize, barriers), then what a frame records from: bind groups, RHI
// barrier lists for both parities, the history textures' first states, frame slots.
#include <hush/core/error.hpp>
#include <hush/graph/render_graph.hpp>

#include "compiled_graph.hpp"
#include "frame_slot.hpp"

namespace hush::graph {

namespace {

// One step's planned barriers (on logical resources) appended to its parity's RHI lists.
void appendBarriers(const GraphModel& m, const CompiledGraph& c, const std::vector<PlannedBarrier>& planned,
                    BarrierLists& out, uint32_t parity) {
    BarrierRange range{.firstTexture = uint32_t(out.textures.size()),
                       .firstBuffer = uint32_t(out.buffers.size()),
                       .firstMemory = uint32_t(out.memory.size())};
    for (const auto& b : planned) {
        const auto& res = m.resources[b.resource];
        if (b.aliased) out.memory.push_back({b.before, b.after});
        if (res.kind == ResourceKind::Texture)
            out.textures.push_back({c.textures[b.resource][parity], b.before, b.after, b.discard});
        else
            out.buffers.push_back({c.buffers[b.resource], b.before, b.after});
    }
    range.textureCount = uint32_t(out.textures.size()) - range.firstTexture;
    range.bufferCount = uint32_t(out.buffers.size()) - range.firstBuffer;
    range.memoryCount = uint32_t(out.memory.size()) - range.firstMemory;
    out.steps.push_back(range);
}

void recordBarrierLists(const GraphModel& m, CompiledGraph& c) {
    for (uint32_t parity = 0; parity < 2; ++parity) {
        auto& lists = c.barrierLists[parity];
        lists = {};
        lists.steps.reserve(c.order.size() + 1);
        for (size_t i = 0; i < c.order.size(); ++i) appendBarriers(m, c, c.barriers.beforePass[i], lists, parity);
        appendBarriers(m, c, c.barriers.frameEnd, lists, parity);
    }
}

// New history textures hold nothing: put them in the states a frame of parity 0
// expects (the caller then marks history invalid, so no frame trusts them).
void initialiseHistoryStates(const rhi::Device& device, const std::string& label, const GraphModel& m,
                             const CompiledGraph& c) {
    std::vector<rhi::TextureBarrier> setup;
    for (uint32_t r = 0; r < m.resources.size(); ++r) {
        if (!c.historyPair[r] || m.resources[r].origin != ResourceOrigin::History) continue;
        const uint32_t s = m.historySource(r);
        // Parity 0 reads history from textures[r][0] (left by the source) and writes the source to textures[s][0].
        const auto sourceEnd = c.barriers.endState[s], historyEnd = c.barriers.endState[r];
        if (sourceEnd != rhi::ResourceState::Undefined)
            setup.push_back({c.textures[r][0], rhi::ResourceState::Undefined, sourceEnd});
        if (historyEnd != rhi::ResourceState::Undefined)
            setup.push_back({c.textures[s][0], rhi::ResourceState::Undefined, historyEnd});
    }
    if (setup.empty()) return;
    auto enc = device.createCommandEncoder({.label = label + ".setup"});
    enc.barrier(setup);
    auto queue = device.queue();
    queue.wait(queue.submit(enc.finish()));
}

} // namespace

void RenderGraph::compile() {
    requireNoRecordedFrames("compile()");
    waitIdle();   // the old resources may still be in use by frames in flight
    validate(model_);
    auto c = std::make_unique<CompiledGraph>();
    c->cull = cull(model_);
    c->order = order(model_, c->cull);
    c->lifetimes = lifetimes(model_, c->order);
    c->outputSize = model_.outputSize;
    static_cast<RealizedResources&>(*c) =
        realize(device_, model_, c->cull, c->order, c->lifetimes,
                {.label = desc_.label, .aliasing = desc_.aliasing, .importedTextures = importedTextures_,
                 .importedBuffers = importedBuffers_});
    std::vector<std::vector<BindGroupDecl>> declared;
    for (const auto& pass : passes_) declared.push_back(pass.bindGroups);
    createBindGroups(device_, model_, declared, *c);
    c->barriers = planBarriers(model_, c->order, c->aliased);
    recordBarrierLists(model_, *c);
    initialiseHistoryStates(device_, desc_.label, model_, *c);
    resetHistory();
    createFrameSlots(*c);
    compiled_ = std::move(c);
    compiledAtFrame_ = frame_;
    dirty_ = false;
    ++compileCount_;
}

// Frame slots and the timings' names, sized once so that frames allocate nothing.
void RenderGraph::createFrameSlots(const CompiledGraph& c) {
    const uint32_t queryCount = uint32_t(2 * c.order.size() + 2);
    slots_.clear();
    slots_.resize(desc_.framesInFlight);
    for (uint32_t i = 0; i < desc_.framesInFlight; ++i) {
        auto& slot = slots_[i];
        slot.encoder = device_.createCommandEncoder(
            {.label = desc_.label + ".frame" + std::to_string(i), .reusable = true, .trackLifetimes = false});
        slot.encoder.finish();   // reset() begins each frame
        if (device_.adapterInfo().limits.timestampsSupported)
            slot.queries = device_.createQuerySet({.label = desc_.label + ".timestamps" + std::to_string(i),
                                                   .count = queryCount});
        slot.ticks.assign(queryCount, 0);
    }
    timings_ = {};
    for (uint32_t p : c.order) timings_.passes.push_back({model_.passes[p].name, 0.0});
}

} // namespace hush::graph
