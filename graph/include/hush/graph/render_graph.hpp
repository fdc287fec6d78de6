#pragma once
// RenderGraph: declare passes and resources once, compile (validate, cull, order,
// alias, plan barriers, create resources and bind groups), then execute frame after
// frame. A frame records one command buffer, with a timestamp pair per pass, and
// allocates nothing; the graph recompiles only when its structure or sizes change.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <hush/graph/compile_steps.hpp>
#include <hush/graph/graph_model.hpp>
#include <hush/graph/handles.hpp>
#include <hush/graph/pass_builder.hpp>
#include <hush/graph/pass_context.hpp>
#include <hush/rhi/device.hpp>

namespace hush::graph {

using ExecuteFn = std::function<void(PassContext&)>;
using SetupFn = std::function<ExecuteFn(PassBuilder&)>;
using PassId = uint32_t;

struct RenderGraphDesc {
    std::string label = "graph";
    uint32_t framesInFlight = 2;   // timings are read from the oldest frame, so reading never stalls
    bool aliasing = true;          // let transients with disjoint lifetimes share memory
};

struct ImportDesc {
    rhi::ResourceState initialState = rhi::ResourceState::SampledRead;   // the state it is in before a frame
    rhi::ResourceState finalState = rhi::ResourceState::SampledRead;     // the state it must be in after
};

struct PassTiming {
    std::string name;
    double gpuMs = 0.0;
};

struct GraphTimings {
    std::vector<PassTiming> passes;   // live passes, in execution order
    double totalGpuMs = 0.0;          // first pass begin to last pass end, barriers included
    double cpuRecordMs = 0.0;         // recording the command buffer on the CPU
    uint64_t frame = 0;               // which frame these are from
    bool valid = false;               // false until a frame has completed
};


struct CompiledGraph;

class RenderGraph {
public:
    explicit RenderGraph(rhi::Device device, const RenderGraphDesc& desc = {});
    ~RenderGraph();
    RenderGraph(const RenderGraph&) = delete;
    RenderGraph& operator=(const RenderGraph&) = delete;

    // Declaration. setup runs now, declares the pass's ports and returns its execute step.
    PassId addPass(const std::string& name, const SetupFn& setup);
    // The typed form (Filament's addPass<Data>): setup fills `data` with the handles
    // the pass produces and returns the execute step; addPass returns `data`, so no
    // handle escapes through a captured local.
    //   struct Out { TextureHandle filtered; };
    //   auto out = graph.addPass<Out>("blur", [&](PassBuilder& b, Out& o) { ...; return execute; });
    template <class Data, class Setup>
    Data addPass(const std::string& name, Setup&& setup) {
        Data data{};
        addPass(name, [&](PassBuilder& builder) -> ExecuteFn { return setup(builder, data); });
        return data;
    }
    TextureHandle importTexture(const std::string& name, const rhi::Texture& texture, const ImportDesc& desc = {});
    BufferHandle importBuffer(const std::string& name, const rhi::Buffer& buffer, const ImportDesc& desc = {});
    // History: last frame's final value of a transient texture. Read-only; holds
    // nothing on the first frame and after resetHistory() (PassContext::historyValid()).
    // Of a texture declared already (one history per texture: asking twice gives the same):
    TextureHandle history(TextureHandle source);
    // Of one declared later, when a pass reads last frame's value of what a later pass
    // makes (feedback, e.g. SVGF's colour history from its first a-trous level): declare
    // it here, then bind it to its source once that exists.
    TextureHandle history(const std::string& name, const TextureInfo& info);
    void bindHistory(TextureHandle history, TextureHandle source);
    void markOutput(TextureHandle texture);
    void markOutput(BufferHandle buffer);
    void setOutputSize(rhi::Extent2D size);   // what relative sizes are relative to
    rhi::Extent2D outputSize() const;
    void resetHistory();                      // e.g. at a camera cut

    // Compile now (execute compiles when needed). Throws hush::Error on an invalid graph.
    void compile();
    bool needsCompile() const;
    // Record and submit one frame.
    rhi::SubmissionId execute();
    // Or record one frame into the caller's encoder (an engine's command buffer, through
    // rhi::encodeIntoVulkanCommandBuffer) between its own commands, without submitting.
    // The caller submits it and calls frameCompleted() once that submission has
    // finished (its fence), oldest frame first; at most framesInFlight such frames may
    // be outstanding, and none across a recompile. Imported textures are expected in
    // their ImportDesc::initialState and left in finalState.
    void record(rhi::CommandEncoder& encoder);
    void frameCompleted();   // reads the oldest recorded frame's timings
    // Waits for the frames execute() submitted (not for those record() left to the caller).
    void waitIdle();

    // After compile: the physical resources behind outputs (valid until the next
    // compile) and the state a frame leaves them in, for reading them back.
    const rhi::Texture& outputTexture(TextureHandle texture) const;
    const rhi::Buffer& outputBuffer(BufferHandle buffer) const;
    rhi::ResourceState outputState(TextureHandle texture) const;

    // Introspection.
    const GraphModel& model() const { return model_; }
    // The newest version of the transient or imported texture (buffer) called `name`
    // (invalid when there is none), and of the texture a history is bound to.
    TextureHandle findTexture(std::string_view name) const;
    BufferHandle findBuffer(std::string_view name) const;
    TextureHandle historySource(TextureHandle history) const;
    const GraphTimings& timings() const { return timings_; }
    MemoryReport memory() const;
    uint32_t compileCount() const { return compileCount_; }
    uint64_t frameCount() const { return frame_; }
    std::vector<std::string> culledPasses() const;
    std::vector<std::string> passOrder() const;
    size_t barrierCount() const;   // barriers recorded per frame, excluding the one-time setup

    // Graphviz DOT and JSON of the compiled graph: passes (culled ones grey),
    // resources with format, extent, lifetime and memory offset, barriers, timings.
    std::string dumpDot() const;
    std::string dumpJson() const;
    // Writes <pathWithoutExtension>.dot and .json (each through a temporary file).
    void writeDump(const std::string& pathWithoutExtension) const;

private:
    friend class PassBuilder;
    struct PassRuntime;
    struct FrameSlot;

    uint32_t addResource(ResourceDecl decl);
    void checkTransient(TextureHandle texture, const char* call) const;
    void markDirty() { dirty_ = true; }
    void readFinishedTimings(FrameSlot& slot);
    FrameSlot& acquireSlot();
    void recordFrame(rhi::CommandEncoder& encoder, FrameSlot& slot);
    void requireNoRecordedFrames(const char* call) const;
    void createFrameSlots(const CompiledGraph& compiled);
    const CompiledGraph& compiled() const;

    rhi::Device device_;
    RenderGraphDesc desc_;
    GraphModel model_;
    std::vector<PassRuntime> passes_;
    std::vector<rhi::Texture> importedTextures_;   // by resource index (empty when not imported)
    std::vector<rhi::Buffer> importedBuffers_;
    std::unique_ptr<CompiledGraph> compiled_;
    std::vector<FrameSlot> slots_;
    GraphTimings timings_;
    bool dirty_ = true;
    bool historyValid_ = false;
    uint32_t compileCount_ = 0;
    uint64_t frame_ = 0;
    uint64_t compiledAtFrame_ = 0;   // parity of history ping-pong counts from here
    uint64_t framesSinceHistoryReset_ = 0;
};

} // namespace hush::graph
