// Step 4: lifetimes and memory aliasing.
#include <algorithm>
#include <numeric>

#include <hush/graph/compile_steps.hpp>

#include "dependencies.hpp"

namespace hush::graph {

std::vector<Lifetime> lifetimes(const GraphModel& m, const std::vector<uint32_t>& passOrder) {
    std::vector<Lifetime> out(m.resources.size());
    for (uint32_t pos = 0; pos < passOrder.size(); ++pos) {
        for (const auto& a : m.passes[passOrder[pos]].accesses) {
            if (!detail::Dependencies::connected(m, a)) continue;
            auto& life = out[a.resource];
            if (!life.used()) life.first = pos;
            life.last = std::max(life.last, pos);
        }
    }
    // Outputs are read after the frame: they live to its end.
    const uint32_t end = passOrder.empty() ? 0 : uint32_t(passOrder.size() - 1);
    for (uint32_t r = 0; r < m.resources.size(); ++r)
        if (m.resources[r].output && out[r].used()) out[r].last = end;
    return out;
}

namespace {
bool overlaps(const Lifetime& a, const Lifetime& b) { return a.first <= b.last && b.first <= a.last; }
uint64_t alignUp(uint64_t v, uint64_t a) { return a <= 1 ? v : (v + a - 1) / a * a; }
} // namespace

AliasPlan planAliasing(const std::vector<AliasItem>& items) {
    AliasPlan plan;
    plan.offsets.assign(items.size(), 0);
    plan.slots.assign(items.size(), 0);
    std::vector<uint32_t> byArea(items.size());
    std::iota(byArea.begin(), byArea.end(), 0u);
    // Largest first: the big textures claim the bottom of the block, smaller ones fill
    // the gaps their lifetimes leave.
    std::stable_sort(byArea.begin(), byArea.end(), [&](uint32_t a, uint32_t b) { return items[a].size > items[b].size; });

    std::vector<uint32_t> placed;
    for (uint32_t i : byArea) {
        const auto& item = items[i];
        plan.unaliasedBytes += alignUp(item.size, item.alignment);
        // Candidate offsets: the start, and the end of every placed item alive at the same time.
        std::vector<uint64_t> candidates{0};
        for (uint32_t j : placed)
            if (overlaps(items[j].lifetime, item.lifetime)) candidates.push_back(plan.offsets[j] + items[j].size);
        std::sort(candidates.begin(), candidates.end());
        uint64_t chosen = 0;
        for (uint64_t c : candidates) {
            const uint64_t offset = alignUp(c, item.alignment);
            bool fits = true;
            for (uint32_t j : placed) {
                if (!overlaps(items[j].lifetime, item.lifetime)) continue;
                const uint64_t a0 = plan.offsets[j], a1 = a0 + items[j].size;
                if (offset < a1 && a0 < offset + item.size) {
                    fits = false;
                    break;
                }
            }
            if (fits) {
                chosen = offset;
                break;
            }
        }
        plan.offsets[i] = chosen;
        plan.slots[i] = i;
        for (uint32_t j : placed)
            if (plan.offsets[j] == chosen) {
                plan.slots[i] = plan.slots[j];
                break;
            }
        plan.blockBytes = std::max(plan.blockBytes, chosen + item.size);
        placed.push_back(i);
    }
    return plan;
}

} // namespace hush::graph
