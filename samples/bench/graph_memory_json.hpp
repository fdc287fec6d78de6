#pragma once
// The graph's memory report as JSON, for hush-bench-graph and hush-bench-chains.
#include <string>

#include <hush/graph/render_graph.hpp>

#include "bench_report.hpp"

namespace hush::bench {

inline std::string memoryJson(const graph::MemoryReport& m) {
    return "{\"transient_aliased_bytes\": " + std::to_string(m.transientAliasedBytes) +
           ", \"transient_unaliased_bytes\": " + std::to_string(m.transientUnaliasedBytes) +
           ", \"history_bytes\": " + std::to_string(m.historyBytes) +
           ", \"output_bytes\": " + std::to_string(m.outputBytes) +
           ", \"transient_textures\": " + std::to_string(m.transientTextures) + "}";
}

inline double mib(uint64_t bytes) { return double(bytes) / (1024.0 * 1024.0); }

} // namespace hush::bench
