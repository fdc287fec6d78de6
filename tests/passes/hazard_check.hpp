#pragma once
// An independent check of a compiled graph's barriers, from its JSON dump
// (RenderGraph::dumpJson) alone: it replays the passes in execution order and
// reports every hazard no barrier covers. It shares no code with graph::planBarriers,
// so a bug there is not repeated here. Why it exists: the Debian validation layer
// (1.3.239) does not report compute-to-compute hazards on storage resources, and
// lavapipe runs dispatches one after another, so a missing barrier passes every
// other test.
//
// Rules, per resource, within a frame:
//  - read after write, write after write, write after read by another pass: a
//    barrier on the resource before the later pass, after the earlier access;
//  - every access happens in the state the last barrier left (layouts);
//  - a barrier's `before` is the state the resource is in (what its source stage
//    and access mask cover);
//  - the first access of every transient in a frame has a barrier (the memory was
//    used by the previous frame); a history starts a frame in the state, and with
//    the uncovered write if any, its source ended the previous one (replayed twice);
//  - a transient placed in memory another transient used earlier in the frame (the
//    aliasing plan: offsets and sizes) gets its first barrier marked `aliased`.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace hush::passes_test {

// Every uncovered hazard, one line each, naming the pass, the resource and the rule.
std::vector<std::string> findHazards(const nlohmann::json& graphDump);

} // namespace hush::passes_test
