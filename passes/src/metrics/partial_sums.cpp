#include <hush/passes/metrics/partial_sums.hpp>

#include <cstring>
#include <string>

#include <hush/core/error.hpp>

namespace hush::passes {

std::array<double, 4> sumPartials(std::span<const float> partials) {
    if (partials.size() != kMetricsPartialFloats)
        throw Error(ErrorKind::InvalidArgument, "metrics: got " + std::to_string(partials.size()) +
                                                    " partial sums, expected " + std::to_string(kMetricsPartialFloats) +
                                                    " (" + std::to_string(kMetricsPartialCount) + " vec4)");
    std::array<double, 4> sums{};
    for (size_t i = 0; i < partials.size(); ++i) sums[i % 4] += double(partials[i]);
    return sums;
}

std::vector<float> readPartials(const rhi::Device& device, const graph::RenderGraph& graph,
                                graph::BufferHandle partials) {
    const auto bytes = device.queue().readBuffer(graph.outputBuffer(partials), 0, kMetricsPartialBytes);
    std::vector<float> values(kMetricsPartialFloats);
    std::memcpy(values.data(), bytes.data(), kMetricsPartialBytes);
    return values;
}

} // namespace hush::passes
