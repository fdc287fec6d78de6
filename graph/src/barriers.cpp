// Step 5: barriers, planned once per compile on logical resources. The executor maps
// them to physical textures (history ping-pong) without further thought.
#include <hush/graph/compile_steps.hpp>

#include "dependencies.hpp"

namespace hush::graph {

namespace {

using rhi::ResourceState;

bool writes(ResourceState s) {
    return s == ResourceState::CopyDst || s == ResourceState::StorageWrite || s == ResourceState::StorageReadWrite ||
           s == ResourceState::HostWrite || s == ResourceState::General;
}

// Image layouts, as far as hazards go: states in one class share a layout.
int layoutClass(ResourceState s) {
    switch (s) {
    case ResourceState::Undefined: return 0;
    case ResourceState::CopySrc: return 1;
    case ResourceState::CopyDst: return 2;
    case ResourceState::SampledRead: return 3;
    default: return 4;   // general
    }
}

bool hazard(ResourceState before, ResourceState after, bool texture) {
    return writes(before) || writes(after) || (texture && layoutClass(before) != layoutClass(after));
}

// How one pass uses one resource, all its ports together.
ResourceState combined(const std::vector<Access>& accesses) {
    bool read = false, write = false;
    for (Access a : accesses) {
        read |= isRead(a);
        write |= isWrite(a);
    }
    const Access first = accesses.front();
    if (read && write) return first == Access::CopySrc || first == Access::CopyDst ? ResourceState::General
                                                                                   : ResourceState::StorageReadWrite;
    for (Access a : accesses)
        if (a != first) return ResourceState::General;   // e.g. storage and uniform reads of one buffer
    return toState(first);
}

struct Use {
    uint32_t position;
    ResourceState state;
};

} // namespace

size_t BarrierPlan::count() const {
    size_t n = frameEnd.size();
    for (const auto& b : beforePass) n += b.size();
    return n;
}

BarrierPlan planBarriers(const GraphModel& m, const std::vector<uint32_t>& passOrder, const std::vector<bool>& aliased) {
    const size_t n = m.resources.size();
    std::vector<std::vector<Use>> uses(n);
    for (uint32_t pos = 0; pos < passOrder.size(); ++pos) {
        std::vector<std::vector<Access>> perResource(n);
        for (const auto& a : m.passes[passOrder[pos]].accesses)
            if (detail::Dependencies::connected(m, a)) perResource[a.resource].push_back(a.access);
        for (uint32_t r = 0; r < n; ++r)
            if (!perResource[r].empty()) uses[r].push_back({pos, combined(perResource[r])});
    }

    BarrierPlan plan;
    plan.beforePass.resize(passOrder.size());
    plan.endState.assign(n, ResourceState::Undefined);
    // End-of-frame states first: the next frame's first barriers start from them.
    std::vector<uint32_t> historyOf(n, kNone);   // source texture -> its history resource
    for (uint32_t r = 0; r < n; ++r) {
        const auto& res = m.resources[r];
        if (res.origin == ResourceOrigin::Imported) plan.endState[r] = res.finalState;
        else if (!uses[r].empty()) plan.endState[r] = uses[r].back().state;
        if (res.origin == ResourceOrigin::History && !uses[r].empty()) {
            const uint32_t source = m.historySource(r);
            if (source != kNone) historyOf[source] = r;
        }
    }
    for (uint32_t r = 0; r < n; ++r)   // an unused history keeps the state its source left
        if (m.resources[r].origin == ResourceOrigin::History && uses[r].empty()) {
            const uint32_t source = m.historySource(r);
            if (source != kNone) plan.endState[r] = plan.endState[source];
        }

    for (uint32_t r = 0; r < n; ++r) {
        const auto& res = m.resources[r];
        const bool texture = res.kind == ResourceKind::Texture;
        if (uses[r].empty()) {
            if (res.origin == ResourceOrigin::Imported && res.initialState != res.finalState &&
                res.finalState != ResourceState::Undefined)
                plan.frameEnd.push_back({r, res.initialState, res.finalState});
            continue;
        }
        // The first use of a frame: where the resource stands when the frame begins.
        const Use& first = uses[r].front();
        PlannedBarrier entry{r, ResourceState::Undefined, first.state};
        const bool overwrites = first.state == ResourceState::StorageWrite || first.state == ResourceState::CopyDst;
        switch (res.origin) {
        case ResourceOrigin::Imported:
            entry.before = res.initialState;
            break;
        case ResourceOrigin::History: {
            const uint32_t source = m.historySource(r);
            entry.before = source == kNone ? ResourceState::Undefined : plan.endState[source];   // it was the source last frame
            entry.historyPhysical = true;
            break;
        }
        case ResourceOrigin::Transient:
            if (historyOf[r] != kNone) {
                entry.before = plan.endState[historyOf[r]];   // it was the history last frame
                entry.discard = overwrites;
            } else if (r < aliased.size() && aliased[r]) {
                entry.before = ResourceState::General;   // another resource used these bytes
                entry.aliased = true;
                entry.discard = true;
            } else {
                entry.before = plan.endState[r];          // itself, last frame
                entry.discard = overwrites;
            }
            break;
        }
        if (entry.discard || entry.aliased || hazard(entry.before, entry.after, texture))
            plan.beforePass[first.position].push_back(entry);

        // Later uses within the frame.
        ResourceState current = first.state;
        bool mergedReads = false;   // reads in different states since the last barrier
        for (size_t i = 1; i < uses[r].size(); ++i) {
            const Use& use = uses[r][i];
            if (hazard(current, use.state, texture)) {
                plan.beforePass[use.position].push_back(
                    {r, mergedReads ? ResourceState::General : current, use.state});
                mergedReads = false;
            } else if (use.state != current) {
                mergedReads = true;   // two kinds of reads: a later write must wait for both
            }
            current = use.state;
        }
        if (res.origin == ResourceOrigin::Imported && hazard(current, res.finalState, texture))
            plan.frameEnd.push_back({r, mergedReads ? ResourceState::General : current, res.finalState});
    }
    return plan;
}

} // namespace hush::graph
