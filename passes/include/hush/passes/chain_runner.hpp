#pragma once
// ChainRunner: a chain in its own graph, fed frame by frame from CPU images and read
// back after each frame. For tools, tests and offline runs (each frame waits for the
// GPU); an engine instead builds the chain into its own graph with its own textures.
#include <array>
#include <memory>
#include <vector>

#include <hush/passes/chain.hpp>
#include <hush/passes/frame_inputs.hpp>

namespace hush::passes {

class ChainRunner {
public:
    // `available`: the channels the frames carry (empty: all); the chain's optional
    // inputs outside it are not read, and the graph culls what only they fed.
    ChainRunner(rhi::Device device, std::unique_ptr<Chain> chain, rhi::Extent2D size,
                const graph::RenderGraphDesc& desc = {}, const std::vector<InputChannel>& available = {});

    // Upload every channel of chain().inputs() here before each run().
    FrameInputs& inputs() { return inputs_; }
    // Executes one frame and waits for it.
    void run();
    void resetHistory() { graph_.resetHistory(); }

    // After run(): the outputs as RGBA floats (width * height * 4), and the count of
    // non-finite input pixels replaced, by InputChannel.
    std::vector<float> readDisplay() const;
    std::vector<float> readRadiance() const;
    // Any rgba32f or rgba16f output of the graph (markOutput), as RGBA floats.
    std::vector<float> readTexture(graph::TextureHandle texture) const;
    std::array<uint32_t, kInputChannelCount> sanitizedCounts() const;

    const Chain& chain() const { return *chain_; }
    graph::RenderGraph& graph() { return graph_; }
    const graph::RenderGraph& graph() const { return graph_; }
    const ChainOutputs& outputs() const { return outputs_; }

private:
    rhi::Device device_;
    std::unique_ptr<Chain> chain_;
    PipelineCache pipelines_;
    graph::RenderGraph graph_;
    FrameInputs inputs_;
    ChainOutputs outputs_;
};

} // namespace hush::passes
