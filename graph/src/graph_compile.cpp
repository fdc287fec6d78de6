// RenderGraph::compile: the steps of compile_steps.hpp, then the physical side:
// textures (aliased in one memory block where lifetimes allow), history pairs, bind
// groups and RHI barrier lists for both frame parities, and the frame slots.
#include <hush/graph/render_graph.hpp>
#include <hush/core/error.hpp>

#include "compiled_graph.hpp"
#include "frame_slot.hpp"

namespace hush::graph {

namespace {

rhi::TextureUsage usageFor(Access access) {
    switch (access) {
    case Access::SampledRead: return rhi::TextureUsage::TextureBinding;
    case Access::CopySrc: return rhi::TextureUsage::CopySrc;
    case Access::CopyDst: return rhi::TextureUsage::CopyDst;
    default: return rhi::TextureUsage::StorageBinding;
    }
}

rhi::BufferUsage bufferUsageFor(Access access) {
    return access == Access::UniformRead ? rhi::BufferUsage::Uniform : rhi::BufferUsage::Storage;
}

} // namespace

void RenderGraph::compile() {
    waitIdle();   // the old resources may still be in use by frames in flight
    validate(model_);
    auto c = std::make_unique<CompiledGraph>();
    c->cull = cull(model_);
    c->order = order(model_, c->cull);
    c->lifetimes = lifetimes(model_, c->order);
    c->outputSize = model_.outputSize;

    const size_t n = model_.resources.size();
    c->extents.resize(n);
    c->aliased.assign(n, false);
    c->memoryOffset.assign(n, kNone);
    c->aliasSlot.assign(n, kNone);
    c->historyPair.assign(n, false);
    c->textureUsage.assign(n, rhi::TextureUsage::None);
    c->textures.resize(n);
    c->buffers.resize(n);
    std::vector<rhi::BufferUsage> bufferUsage(n, rhi::BufferUsage::None);
    for (uint32_t p : c->order)
        for (const auto& a : model_.passes[p].accesses) {
            if (a.resource >= n) continue;
            c->textureUsage[a.resource] |= usageFor(a.access);
            bufferUsage[a.resource] |= bufferUsageFor(a.access);
        }
    for (uint32_t r = 0; r < n; ++r) {
        const auto& res = model_.resources[r];
        if (res.kind == ResourceKind::Texture) c->extents[r] = res.texture.size.resolve(model_.outputSize);
        // Outputs and histories are read back and copied by tools and tests.
        if (res.output || res.origin == ResourceOrigin::History) c->textureUsage[r] |= rhi::TextureUsage::CopySrc;
    }

    // History pairs: a source and its history share two textures and swap each frame.
    for (uint32_t h = 0; h < n; ++h) {
        const auto& res = model_.resources[h];
        if (res.origin != ResourceOrigin::History || !c->cull.resourceUsed[h]) continue;
        const uint32_t s = model_.historySource(h);
        const auto usage = c->textureUsage[h] | c->textureUsage[s] | rhi::TextureUsage::CopySrc;
        std::array<rhi::Texture, 2> pair;
        for (int i = 0; i < 2; ++i)
            pair[i] = device_.createTexture({.label = res.name + (i ? ".history.b" : ".history.a"),
                                             .size = c->extents[h], .format = res.texture.format, .usage = usage});
        c->textures[s] = {pair[0], pair[1]};
        c->textures[h] = {pair[1], pair[0]};
        c->historyPair[s] = c->historyPair[h] = true;
        c->memory.historyBytes += 2 * pair[0].byteSize();
    }

    // Transient textures: the aliasing candidates share one memory block.
    std::vector<uint32_t> candidates;
    std::vector<AliasItem> items;
    for (uint32_t r = 0; r < n; ++r) {
        const auto& res = model_.resources[r];
        if (!c->cull.resourceUsed[r] || c->historyPair[r]) continue;
        if (res.origin == ResourceOrigin::Imported) {
            if (res.kind == ResourceKind::Texture) c->textures[r] = {importedTextures_[r], importedTextures_[r]};
            else c->buffers[r] = importedBuffers_[r];
            continue;
        }
        if (res.kind == ResourceKind::Buffer) {
            c->buffers[r] = device_.createBuffer({.label = res.name, .size = res.buffer.resolve(model_.outputSize),
                                                  .usage = bufferUsage[r] | rhi::BufferUsage::CopySrc |
                                                           rhi::BufferUsage::CopyDst});
            continue;
        }
        const rhi::TextureDesc desc{.label = res.name, .size = c->extents[r], .format = res.texture.format,
                                    .usage = c->textureUsage[r]};
        if (res.output || !desc_.aliasing) {
            auto t = device_.createTexture(desc);
            c->textures[r] = {t, t};
            c->memory.outputBytes += res.output ? t.byteSize() : 0;
            if (!res.output) c->memory.transientUnaliasedBytes += device_.textureMemoryRequirements(desc).size;
            if (!res.output) c->memory.transientAliasedBytes += device_.textureMemoryRequirements(desc).size;
            ++c->memory.transientTextures;
            continue;
        }
        const auto req = device_.textureMemoryRequirements(desc);
        candidates.push_back(r);
        items.push_back({req.size, req.alignment, c->lifetimes[r]});
    }
    if (!candidates.empty()) {
        const AliasPlan plan = planAliasing(items);
        uint32_t typeBits = ~0u;
        for (uint32_t r : candidates) {
            const auto& res = model_.resources[r];
            typeBits &= device_.textureMemoryRequirements({.label = res.name, .size = c->extents[r],
                                                           .format = res.texture.format, .usage = c->textureUsage[r]})
                            .memoryTypeBits;
        }
        c->transientBlock = device_.createMemoryBlock({.label = desc_.label + ".transients", .size = plan.blockBytes,
                                                       .memoryTypeBits = typeBits});
        for (size_t i = 0; i < candidates.size(); ++i) {
            const uint32_t r = candidates[i];
            const auto& res = model_.resources[r];
            auto t = device_.createTexture({.label = res.name, .size = c->extents[r], .format = res.texture.format,
                                            .usage = c->textureUsage[r]},
                                           c->transientBlock, plan.offsets[i]);
            c->textures[r] = {t, t};
            c->memoryOffset[r] = plan.offsets[i];
            c->aliasSlot[r] = candidates[plan.slots[i]];
            for (size_t j = 0; j < candidates.size(); ++j)
                if (j != i && plan.offsets[i] < plan.offsets[j] + items[j].size &&
                    plan.offsets[j] < plan.offsets[i] + items[i].size)
                    c->aliased[r] = true;
        }
        c->memory.transientAliasedBytes += plan.blockBytes;
        c->memory.transientUnaliasedBytes += plan.unaliasedBytes;
        c->memory.transientTextures += uint32_t(candidates.size());
    }

    // Bind groups, for both parities, checked against the pipelines' layouts.
    c->bindGroups.resize(model_.passes.size());
    c->bindGroupSets.resize(model_.passes.size());
    for (uint32_t p : c->order) {
        const auto& pass = model_.passes[p];
        for (const auto& decl : passes_[p].bindGroups) {
            std::array<rhi::BindGroup, 2> groups;
            for (uint32_t parity = 0; parity < 2; ++parity) {
                rhi::BindGroupDesc bg{.label = pass.name + ".set" + std::to_string(decl.set),
                                      .layout = decl.pipeline.getBindGroupLayout(decl.set), .entries = {}};
                for (const auto& b : decl.bindings) {
                    rhi::BindGroupEntry e{.binding = b.binding, .name = b.name};
                    const uint32_t r = b.texture.valid() ? b.texture.index : b.buffer.valid() ? b.buffer.index : kNone;
                    if (r != kNone) {
                        bool declared = false;
                        for (const auto& a : pass.accesses) declared |= a.resource == r;
                        if (!declared || r >= n)
                            throw Error(ErrorKind::InvalidArgument,
                                        "pass '" + pass.name + "' binds '" + (r < n ? model_.resources[r].name : "?") +
                                            "' to '" + (b.name.empty() ? "binding " + std::to_string(b.binding) : b.name) +
                                            "' but declares no read or write of it");
                    }
                    if (b.texture.valid()) e.texture = c->textures[r][parity];
                    else if (b.buffer.valid()) e.buffer = c->buffers[r];
                    else e.buffer = b.fixedBuffer;
                    e.sampler = b.sampler;
                    bg.entries.push_back(std::move(e));
                }
                try {
                    groups[parity] = device_.createBindGroup(bg);
                } catch (const Error& e) {
                    throw Error(e.kind(), "pass '" + pass.name + "': " + e.what());
                }
            }
            c->bindGroups[p].push_back(groups);
            c->bindGroupSets[p].push_back(decl.set);
        }
    }

    // Barriers: planned on logical resources, then turned into RHI lists per parity.
    c->barriers = planBarriers(model_, c->order, c->aliased);
    auto record = [&](const std::vector<PlannedBarrier>& planned, RecordedBarriers& out, uint32_t parity) {
        for (const auto& b : planned) {
            const auto& res = model_.resources[b.resource];
            if (b.aliased) out.memory.push_back({b.before, b.after});
            if (res.kind == ResourceKind::Texture)
                out.textures.push_back({c->textures[b.resource][parity], b.before, b.after, b.discard});
            else
                out.buffers.push_back({c->buffers[b.resource], b.before, b.after});
        }
    };
    c->passBarriers.resize(c->order.size());
    for (uint32_t parity = 0; parity < 2; ++parity) {
        for (size_t i = 0; i < c->order.size(); ++i) record(c->barriers.beforePass[i], c->passBarriers[i][parity], parity);
        record(c->barriers.frameEnd, c->frameEndBarriers[parity], parity);
    }

    // New history textures hold nothing: put them in the states a frame expects and
    // mark history invalid, so the next frame does not trust them.
    std::vector<rhi::TextureBarrier> setup;
    for (uint32_t r = 0; r < n; ++r) {
        if (!c->historyPair[r] || model_.resources[r].origin != ResourceOrigin::History) continue;
        const uint32_t s = model_.historySource(r);
        // Parity 0 reads history from textures[r][0] (left by the source) and writes the source to textures[s][0].
        const auto sourceEnd = c->barriers.endState[s], historyEnd = c->barriers.endState[r];
        if (sourceEnd != rhi::ResourceState::Undefined)
            setup.push_back({c->textures[r][0], rhi::ResourceState::Undefined, sourceEnd});
        if (historyEnd != rhi::ResourceState::Undefined)
            setup.push_back({c->textures[s][0], rhi::ResourceState::Undefined, historyEnd});
    }
    if (!setup.empty()) {
        auto enc = device_.createCommandEncoder({.label = desc_.label + ".setup"});
        enc.barrier(setup);
        auto queue = device_.queue();
        queue.wait(queue.submit(enc.finish()));
    }
    resetHistory();

    // Frame slots and the timings' names, sized once so that frames allocate nothing.
    const uint32_t queryCount = uint32_t(2 * c->order.size() + 2);
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
    for (uint32_t p : c->order) timings_.passes.push_back({model_.passes[p].name, 0.0});
    compiled_ = std::move(c);
    compiledAtFrame_ = frame_;
    dirty_ = false;
    ++compileCount_;
}

} // namespace hush::graph
