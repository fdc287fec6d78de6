// Step 6, realize: the physical textures and buffers of a planned graph.
#include <hush/core/error.hpp>
#include <hush/graph/compile_steps.hpp>

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
    switch (access) {
    case Access::UniformRead: return rhi::BufferUsage::Uniform;
    case Access::IndirectRead: return rhi::BufferUsage::Indirect | rhi::BufferUsage::Storage;
    default: return rhi::BufferUsage::Storage;
    }
}

// Usages from every live access; outputs and histories are also read back by tools.
void collectUsages(const GraphModel& m, const std::vector<uint32_t>& order, RealizedResources& r,
                   std::vector<rhi::BufferUsage>& bufferUsage) {
    const size_t n = m.resources.size();
    for (uint32_t p : order)
        for (const auto& a : m.passes[p].accesses) {
            if (a.resource >= n) continue;
            r.textureUsage[a.resource] |= usageFor(a.access);
            bufferUsage[a.resource] |= bufferUsageFor(a.access);
        }
    for (uint32_t i = 0; i < n; ++i) {
        const auto& res = m.resources[i];
        if (res.kind == ResourceKind::Texture) r.extents[i] = res.texture.size.resolve(m.outputSize);
        if (res.output || res.origin == ResourceOrigin::History) r.textureUsage[i] |= rhi::TextureUsage::CopySrc;
    }
}

// A source and its history share two textures and swap them every frame.
void realizeHistoryPairs(const rhi::Device& device, const GraphModel& m, const CullResult& culled, RealizedResources& r) {
    for (uint32_t h = 0; h < m.resources.size(); ++h) {
        const auto& res = m.resources[h];
        if (res.origin != ResourceOrigin::History || !culled.resourceUsed[h]) continue;
        const uint32_t s = m.historySource(h);
        const auto usage = r.textureUsage[h] | r.textureUsage[s] | rhi::TextureUsage::CopySrc;
        std::array<rhi::Texture, 2> pair;
        for (int i = 0; i < 2; ++i)
            pair[i] = device.createTexture({.label = res.name + (i ? ".history.b" : ".history.a"), .size = r.extents[h],
                                            .format = res.texture.format, .usage = usage});
        r.textures[s] = {pair[0], pair[1]};
        r.textures[h] = {pair[1], pair[0]};
        r.historyPair[s] = r.historyPair[h] = true;
        r.memory.historyBytes += 2 * pair[0].byteSize();
    }
}

rhi::TextureDesc textureDesc(const GraphModel& m, const RealizedResources& r, uint32_t i) {
    const auto& res = m.resources[i];
    return {.label = res.name, .size = r.extents[i], .format = res.texture.format, .usage = r.textureUsage[i]};
}

// The aliasing candidates, placed in one memory block.
void realizeAliased(const rhi::Device& device, const GraphModel& m, const std::vector<Lifetime>& lifetimes,
                    const std::vector<uint32_t>& candidates, const std::string& label, RealizedResources& r) {
    if (candidates.empty()) return;
    std::vector<AliasItem> items;
    uint32_t typeBits = ~0u;
    for (uint32_t i : candidates) {
        const auto req = device.textureMemoryRequirements(textureDesc(m, r, i));
        items.push_back({req.size, req.alignment, lifetimes[i]});
        typeBits &= req.memoryTypeBits;
    }
    const AliasPlan plan = planAliasing(items);
    r.transientBlock = device.createMemoryBlock({.label = label + ".transients", .size = plan.blockBytes,
                                                 .memoryTypeBits = typeBits});
    for (size_t k = 0; k < candidates.size(); ++k) {
        const uint32_t i = candidates[k];
        const auto t = device.createTexture(textureDesc(m, r, i), r.transientBlock, plan.offsets[k]);
        r.textures[i] = {t, t};
        r.memoryOffset[i] = plan.offsets[k];
        r.aliasSlot[i] = candidates[plan.slots[k]];
        for (size_t j = 0; j < candidates.size(); ++j)
            if (j != k && plan.offsets[k] < plan.offsets[j] + items[j].size &&
                plan.offsets[j] < plan.offsets[k] + items[k].size)
                r.aliased[i] = true;
    }
    r.memory.transientAliasedBytes += plan.blockBytes;
    r.memory.transientUnaliasedBytes += plan.unaliasedBytes;
    r.memory.transientTextures += uint32_t(candidates.size());
}

} // namespace

RealizedResources realize(const rhi::Device& device, const GraphModel& m, const CullResult& culled,
                          const std::vector<uint32_t>& order, const std::vector<Lifetime>& lifetimes,
                          const RealizeOptions& options) {
    const size_t n = m.resources.size();
    RealizedResources r;
    r.extents.resize(n);
    r.aliased.assign(n, false);
    r.memoryOffset.assign(n, kNone);
    r.aliasSlot.assign(n, kNone);
    r.historyPair.assign(n, false);
    r.textureUsage.assign(n, rhi::TextureUsage::None);
    r.textures.resize(n);
    r.buffers.resize(n);
    std::vector<rhi::BufferUsage> bufferUsage(n, rhi::BufferUsage::None);
    collectUsages(m, order, r, bufferUsage);
    realizeHistoryPairs(device, m, culled, r);

    std::vector<uint32_t> candidates;
    for (uint32_t i = 0; i < n; ++i) {
        const auto& res = m.resources[i];
        if (!culled.resourceUsed[i] || r.historyPair[i]) continue;
        if (res.origin == ResourceOrigin::Imported) {
            if (res.kind == ResourceKind::Texture) r.textures[i] = {options.importedTextures[i], options.importedTextures[i]};
            else r.buffers[i] = options.importedBuffers[i];
            continue;
        }
        if (res.kind == ResourceKind::Buffer) {
            r.buffers[i] = device.createBuffer({.label = res.name, .size = res.buffer.resolve(m.outputSize),
                                                .usage = bufferUsage[i] | rhi::BufferUsage::CopySrc |
                                                         rhi::BufferUsage::CopyDst});
            continue;
        }
        if (!res.output && options.aliasing) {
            candidates.push_back(i);
            continue;
        }
        // Outputs are read back after the frame, so they never share memory.
        const auto desc = textureDesc(m, r, i);
        const auto t = device.createTexture(desc);
        r.textures[i] = {t, t};
        ++r.memory.transientTextures;
        if (res.output) {
            r.memory.outputBytes += t.byteSize();
        } else {
            const uint64_t bytes = device.textureMemoryRequirements(desc).size;
            r.memory.transientUnaliasedBytes += bytes;
            r.memory.transientAliasedBytes += bytes;
        }
    }
    realizeAliased(device, m, lifetimes, candidates, options.label, r);
    return r;
}

} // namespace hush::graph
