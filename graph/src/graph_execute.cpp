// RenderGraph::execute: record one frame into a reusable command buffer (barriers
// planned at compile time, a timestamp pair per pass), submit it, and read the
// timings of the oldest frame in flight once it has finished. Nothing here allocates.
#include <chrono>

#include <hush/graph/render_graph.hpp>
#include <hush/core/error.hpp>

#include "compiled_graph.hpp"
#include "frame_slot.hpp"

namespace hush::graph {

namespace {

void recordBarriers(rhi::CommandEncoder& encoder, const RecordedBarriers& b) {
    if (!b.empty()) encoder.barrier(b.textures, b.buffers, b.memory);
}

} // namespace

rhi::SubmissionId RenderGraph::execute() {
    if (needsCompile()) compile();
    const auto& c = *compiled_;
    auto queue = device_.queue();
    auto& slot = slots_[frame_ % slots_.size()];
    if (slot.submission) {
        queue.wait(slot.submission);   // bounds the frames in flight
        readFinishedTimings(slot);
    }

    const auto start = std::chrono::steady_clock::now();
    auto& enc = slot.encoder;
    enc.reset();
    const bool timed = bool(slot.queries);
    const uint32_t parity = uint32_t((frame_ - compiledAtFrame_) % 2);
    historyValid_ = framesSinceHistoryReset_ > 0;
    if (timed) enc.writeTimestamp(slot.queries, 0);
    for (size_t i = 0; i < c.order.size(); ++i) {
        const uint32_t p = c.order[i];
        recordBarriers(enc, c.passBarriers[i][parity]);
        if (timed) enc.writeTimestamp(slot.queries, uint32_t(1 + 2 * i));
        PassContext ctx(c, enc, parity, historyValid_, frame_, framesSinceHistoryReset_);
        passes_[p].execute(ctx);
        if (timed) enc.writeTimestamp(slot.queries, uint32_t(2 + 2 * i));
    }
    recordBarriers(enc, c.frameEndBarriers[parity]);
    if (timed) enc.writeTimestamp(slot.queries, uint32_t(1 + 2 * c.order.size()));
    const auto commands = enc.finish();
    slot.cpuRecordMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    slot.submission = queue.submit(commands);
    slot.frame = frame_;
    slot.timingsPending = timed;
    ++frame_;
    ++framesSinceHistoryReset_;
    return slot.submission;
}

void RenderGraph::readFinishedTimings(FrameSlot& slot) {
    if (!slot.timingsPending) return;
    slot.timingsPending = false;
    slot.queries.readTicks(0, slot.ticks);
    const double msPerTick = device_.adapterInfo().limits.timestampPeriodNs * 1e-6;
    const auto& t = slot.ticks;
    for (size_t i = 0; i < timings_.passes.size(); ++i)
        timings_.passes[i].gpuMs = double(t[2 + 2 * i] - t[1 + 2 * i]) * msPerTick;
    timings_.totalGpuMs = double(t.back() - t.front()) * msPerTick;
    timings_.cpuRecordMs = slot.cpuRecordMs;
    timings_.frame = slot.frame;
    timings_.valid = true;
}

void RenderGraph::waitIdle() {
    if (slots_.empty()) return;
    auto queue = device_.queue();
    // Oldest first, so the timings left are the newest frame's.
    for (size_t k = 0; k < slots_.size(); ++k) {
        auto& slot = slots_[(frame_ + k) % slots_.size()];
        if (!slot.submission) continue;
        queue.wait(slot.submission);
        readFinishedTimings(slot);
    }
}

const rhi::Texture& PassContext::texture(TextureHandle handle) const {
    if (handle.index >= graph_.textures.size() || !graph_.textures[handle.index][parity_])
        throw Error(ErrorKind::InvalidArgument, "PassContext::texture: the handle names no live texture");
    return graph_.textures[handle.index][parity_];
}

const rhi::Buffer& PassContext::buffer(BufferHandle handle) const {
    if (handle.index >= graph_.buffers.size() || !graph_.buffers[handle.index])
        throw Error(ErrorKind::InvalidArgument, "PassContext::buffer: the handle names no live buffer");
    return graph_.buffers[handle.index];
}

const rhi::BindGroup& PassContext::bindGroup(BindGroupHandle handle) const {
    if (handle.pass >= graph_.bindGroups.size() || handle.index >= graph_.bindGroups[handle.pass].size())
        throw Error(ErrorKind::InvalidArgument, "PassContext::bindGroup: the handle was not declared by a live pass");
    return graph_.bindGroups[handle.pass][handle.index][parity_];
}

rhi::Extent2D PassContext::outputSize() const { return graph_.outputSize; }

void PassContext::dispatch(const rhi::ComputePipeline& pipeline, BindGroupHandle group, rhi::Extent2D threads,
                           uint32_t layers, const rhi::PushConstants* params) {
    auto pass = encoder_.beginComputePass();
    pass.setPipeline(pipeline);
    pass.setBindGroup(graph_.bindGroupSets[group.pass][group.index], bindGroup(group));
    if (params) pass.setPushConstants(*params);
    pass.dispatchThreads(threads.width, threads.height, layers);
    pass.end();
}

} // namespace hush::graph
