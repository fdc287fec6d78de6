#pragma once
// One frame in flight: its reusable encoder, its timestamps and when it was submitted.
#include <vector>

#include <hush/graph/render_graph.hpp>

namespace hush::graph {

struct RenderGraph::FrameSlot {
    rhi::CommandEncoder encoder;
    rhi::QuerySet queries;              // frame begin, (begin, end) per pass, frame end
    std::vector<uint64_t> ticks;        // read back here, sized once
    rhi::SubmissionId submission = 0;   // 0: nothing in flight
    uint64_t frame = 0;
    double cpuRecordMs = 0.0;
    bool timingsPending = false;
    // Recorded into a caller's command buffer (RenderGraph::record): the caller submits
    // it and reports its completion (frameCompleted); hush cannot wait for it.
    bool external = false;
};

} // namespace hush::graph
