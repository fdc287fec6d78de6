#pragma once
// JSON pieces the graph-based benchmarks (hush-bench-graph, hush-bench-chains) share.
#include <cstdio>
#include <string>

#include <hush/graph/render_graph.hpp>

#include "bench_report.hpp"

namespace hush::bench {

// %.6g: enough digits for timings, no trailing noise.
inline std::string jsonNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

inline std::string statsJson(const Stats& s) {
    return "{\"median\": " + jsonNumber(s.median) + ", \"min\": " + jsonNumber(s.min) + ", \"max\": " +
           jsonNumber(s.max) + "}";
}

inline std::string memoryJson(const graph::MemoryReport& m) {
    return "{\"transient_aliased_bytes\": " + std::to_string(m.transientAliasedBytes) +
           ", \"transient_unaliased_bytes\": " + std::to_string(m.transientUnaliasedBytes) +
           ", \"history_bytes\": " + std::to_string(m.historyBytes) +
           ", \"output_bytes\": " + std::to_string(m.outputBytes) +
           ", \"transient_textures\": " + std::to_string(m.transientTextures) + "}";
}

inline double mib(uint64_t bytes) { return double(bytes) / (1024.0 * 1024.0); }

} // namespace hush::bench
