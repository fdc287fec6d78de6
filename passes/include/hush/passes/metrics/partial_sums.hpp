#pragma once
// How the metric nodes reduce an image to a few numbers: every metric pass runs on
// a fixed grid of kMetricsPartialCount workgroups (16 x 16 of 16 x 16 invocations,
// whatever the image size; each invocation loops over the pixels a grid-stride
// apart), adds its invocations' fp32 sums in shared memory and writes one vec4 per
// workgroup into a buffer of partial sums. The host reads the buffer back and adds
// the partials in double precision. A fixed count keeps the buffer's size right
// when the graph's output size changes, and every entry is written each frame.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <hush/graph/render_graph.hpp>

namespace hush::passes {

inline constexpr uint32_t kMetricsGroupSize = 16;    // invocations per axis of a workgroup
inline constexpr uint32_t kMetricsGridGroups = 16;   // workgroups per axis of the grid
inline constexpr uint32_t kMetricsGridThreads = kMetricsGroupSize * kMetricsGridGroups;   // dispatched per axis
inline constexpr uint32_t kMetricsPartialCount = kMetricsGridGroups * kMetricsGridGroups;
inline constexpr uint32_t kMetricsPartialFloats = kMetricsPartialCount * 4;   // one vec4 each
inline constexpr uint64_t kMetricsPartialBytes = kMetricsPartialFloats * sizeof(float);

// The buffer a metric pass writes its partials into.
inline graph::BufferInfo metricsPartialsInfo() { return {kMetricsPartialBytes}; }

// The four components of the partials, each added over all workgroups in double.
// Throws hush::Error (InvalidArgument) unless there are kMetricsPartialFloats values.
std::array<double, 4> sumPartials(std::span<const float> partials);

// Reads a partials buffer the graph marked as output, after graph.waitIdle().
std::vector<float> readPartials(const rhi::Device& device, const graph::RenderGraph& graph,
                                graph::BufferHandle partials);

} // namespace hush::passes
