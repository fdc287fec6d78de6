// RenderGraph::execute: record one frame into a reusable command buffer (barriers
// planned at compile time, a timestamp pair per pass), submit it, and read the
// timings of the oldest frame in flight once it has finished. Nothing here allocates.
// RenderGraph::record does the same into a caller's command buffer, which the caller
// submits (an engine's frame).
#include <chrono>
#include <span>

#include <hush/graph/render_graph.hpp>
#include <hush/core/error.hpp>

#include "compiled_graph.hpp"
#include "frame_slot.hpp"

namespace hush::graph {

namespace {

void recordBarriers(rhi::CommandEncoder& encoder, const BarrierLists& lists, size_t step) {
    const auto& r = lists.steps[step];
    if (r.empty()) return;
    encoder.barrier(std::span(lists.textures).subspan(r.firstTexture, r.textureCount),
                    std::span(lists.buffers).subspan(r.firstBuffer, r.bufferCount),
                    std::span(lists.memory).subspan(r.firstMemory, r.memoryCount));
}

} // namespace

RenderGraph::FrameSlot& RenderGraph::acquireSlot() {
    if (needsCompile()) compile();
    auto& slot = slots_[frame_ % slots_.size()];
    if (slot.external)
        throw Error(ErrorKind::InvalidArgument,
                    "render graph '" + desc_.label + "': frame " + std::to_string(slot.frame) +
                        " was recorded into the caller's command buffer (record()) and not reported finished: call "
                        "frameCompleted() once its submission completes (at most " +
                        std::to_string(slots_.size()) + " such frames in flight)");
    if (slot.submission) {
        device_.queue().wait(slot.submission);   // bounds the frames in flight
        slot.submission = 0;
        readFinishedTimings(slot);
    }
    return slot;
}

void RenderGraph::recordFrame(rhi::CommandEncoder& enc, FrameSlot& slot) {
    const auto& c = *compiled_;
    const auto start = std::chrono::steady_clock::now();
    const bool timed = bool(slot.queries);
    const uint32_t parity = uint32_t((frame_ - compiledAtFrame_) % 2);
    historyValid_ = framesSinceHistoryReset_ > 0;
    const auto& barriers = c.barrierLists[parity];
    if (timed) enc.writeTimestamp(slot.queries, 0);
    for (size_t i = 0; i < c.order.size(); ++i) {
        const uint32_t p = c.order[i];
        recordBarriers(enc, barriers, i);
        if (timed) enc.writeTimestamp(slot.queries, uint32_t(1 + 2 * i));
        PassContext ctx(c, enc, parity, historyValid_, frame_, framesSinceHistoryReset_);
        passes_[p].execute(ctx);
        if (timed) enc.writeTimestamp(slot.queries, uint32_t(2 + 2 * i));
    }
    recordBarriers(enc, barriers, c.order.size());
    if (timed) enc.writeTimestamp(slot.queries, uint32_t(1 + 2 * c.order.size()));
    slot.cpuRecordMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    slot.frame = frame_;
    slot.timingsPending = timed;
    ++frame_;
    ++framesSinceHistoryReset_;
}

rhi::SubmissionId RenderGraph::execute() {
    auto& slot = acquireSlot();
    slot.encoder.reset();
    recordFrame(slot.encoder, slot);
    slot.submission = device_.queue().submit(slot.encoder.finish());
    return slot.submission;
}

void RenderGraph::record(rhi::CommandEncoder& encoder) {
    auto& slot = acquireSlot();
    recordFrame(encoder, slot);
    slot.external = true;
}

void RenderGraph::frameCompleted() {
    for (size_t k = 0; k < slots_.size(); ++k) {   // oldest first
        auto& slot = slots_[(frame_ + k) % slots_.size()];
        if (!slot.external) continue;
        slot.external = false;
        readFinishedTimings(slot);
        return;
    }
    throw Error(ErrorKind::InvalidArgument,
                "render graph '" + desc_.label + "': frameCompleted() without a frame recorded by record() in flight");
}

void RenderGraph::requireNoRecordedFrames(const char* call) const {
    for (const auto& slot : slots_)
        if (slot.external)
            throw Error(ErrorKind::InvalidArgument,
                        "render graph '" + desc_.label + "': " + call + " while frame " + std::to_string(slot.frame) +
                            " recorded by record() may still run: wait for it and call frameCompleted() first");
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
        if (!slot.submission || slot.external) continue;
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

namespace {

const PassBindGroup& boundGroup(const CompiledGraph& graph, BindGroupHandle handle) {
    if (handle.pass >= graph.bindGroupRanges.size() || handle.index >= graph.bindGroupRanges[handle.pass].count)
        throw Error(ErrorKind::InvalidArgument, "PassContext::bindGroup: the handle was not declared by a live pass");
    return graph.bindGroups[graph.bindGroupRanges[handle.pass].first + handle.index];
}

} // namespace

const rhi::BindGroup& PassContext::bindGroup(BindGroupHandle handle) const {
    return boundGroup(graph_, handle).groups[parity_];
}

rhi::Extent2D PassContext::outputSize() const { return graph_.outputSize; }

void PassContext::dispatch(const rhi::ComputePipeline& pipeline, BindGroupHandle group, rhi::Extent2D threads,
                           uint32_t layers, const rhi::PushConstants* params) {
    auto pass = encoder_.beginComputePass();
    pass.setPipeline(pipeline);
    const auto& bound = boundGroup(graph_, group);
    pass.setBindGroup(bound.set, bound.groups[parity_]);
    if (params) pass.setPushConstants(*params);
    pass.dispatchThreads(threads.width, threads.height, layers);
    pass.end();
}

void PassContext::dispatchIndirect(const rhi::ComputePipeline& pipeline, BindGroupHandle group, BufferHandle counts,
                                   const rhi::PushConstants& params, uint64_t offset) {
    auto pass = encoder_.beginComputePass();
    pass.setPipeline(pipeline);
    const auto& bound = boundGroup(graph_, group);
    pass.setBindGroup(bound.set, bound.groups[parity_]);
    pass.setPushConstants(params);
    pass.dispatchWorkgroupsIndirect(buffer(counts), offset);
    pass.end();
}

} // namespace hush::graph
