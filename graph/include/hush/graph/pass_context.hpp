#pragma once
// PassContext: what a pass's execute step records with. It resolves handles to the
// physical resources of this frame (history ping-pong included) and hands out the
// bind groups the setup step declared. Nothing here allocates.
#include <cstdint>

#include <hush/graph/handles.hpp>
#include <hush/rhi/command.hpp>
#include <hush/rhi/push_constants.hpp>

namespace hush::graph {

struct CompiledGraph;

class PassContext {
public:
    rhi::CommandEncoder& encoder() const { return encoder_; }
    const rhi::Texture& texture(TextureHandle handle) const;
    const rhi::Buffer& buffer(BufferHandle handle) const;
    const rhi::BindGroup& bindGroup(BindGroupHandle handle) const;
    // False on the first frame and after resetHistory(): the history holds nothing.
    bool historyValid() const { return historyValid_; }
    rhi::Extent2D outputSize() const;
    uint64_t frameIndex() const { return frame_; }
    // Frames since the history was last reset (0 on the first frame and after
    // resetHistory()): what a pattern that varies frame by frame should count, so that
    // a chain after a cut does what a new chain does.
    uint64_t historyFrame() const { return historyFrame_; }

    // The common case: one dispatch of `pipeline` with one bind group (at the set it
    // was declared for) covering threads.width x threads.height invocations, with its
    // push constants (written by name, rhi/push_constants.hpp) when it has any.
    void dispatch(const rhi::ComputePipeline& pipeline, BindGroupHandle group, rhi::Extent2D threads) {
        dispatch(pipeline, group, threads, 1, nullptr);
    }
    void dispatch(const rhi::ComputePipeline& pipeline, BindGroupHandle group, rhi::Extent2D threads,
                  const rhi::PushConstants& params) {
        dispatch(pipeline, group, threads, 1, &params);
    }
    // The same over `layers` slices in z (e.g. a tensor's channel blocks).
    void dispatch(const rhi::ComputePipeline& pipeline, BindGroupHandle group, rhi::Extent2D threads, uint32_t layers,
                  const rhi::PushConstants& params) {
        dispatch(pipeline, group, threads, layers, &params);
    }

    // One dispatch whose workgroup counts the GPU wrote into `counts` (declared with
    // PassBuilder::readIndirect by this pass), at byte `offset`.
    void dispatchIndirect(const rhi::ComputePipeline& pipeline, BindGroupHandle group, BufferHandle counts,
                          const rhi::PushConstants& params, uint64_t offset = 0);

    PassContext(const CompiledGraph& graph, rhi::CommandEncoder& encoder, uint32_t parity, bool historyValid,
                uint64_t frame, uint64_t historyFrame)
        : graph_(graph), encoder_(encoder), parity_(parity), historyValid_(historyValid), frame_(frame),
          historyFrame_(historyFrame) {}

private:
    void dispatch(const rhi::ComputePipeline& pipeline, BindGroupHandle group, rhi::Extent2D threads, uint32_t layers,
                  const rhi::PushConstants* params);

    const CompiledGraph& graph_;
    rhi::CommandEncoder& encoder_;
    uint32_t parity_;
    bool historyValid_;
    uint64_t frame_;
    uint64_t historyFrame_;
};

} // namespace hush::graph
