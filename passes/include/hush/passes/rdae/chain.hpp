#pragma once
// RdaeChain: Chaitanya et al. 2017, "Interactive Reconstruction of Monte Carlo Image
// Sequences using a Recurrent Denoising Autoencoder" (seed 004; docs/passes/rdae.md):
//   front end (sanitize; surface and reprojection for TAA) -> demodulate the colour
//   -> input tensor (colour^0.2, view-space normal, depth, roughness)
//   -> the network (architecture.hpp; every convolution a graph pass, the RCNN
//      blocks' hidden states graph histories) -> crop, ^5 -> remodulate
//   -> back end (tonemap, TAA as the paper's Sec. 5.1)
// The weights come from a file in the safetensors layout, or the ones hush ships for
// this width and depth.
#include <memory>
#include <string>

#include <hush/passes/chain.hpp>
#include <hush/passes/chain_back_end.hpp>
#include <hush/passes/chain_front_end.hpp>
#include <hush/passes/rdae/network.hpp>

namespace hush::passes {

struct RdaeSettings {
    ChainFrontSettings front;
    // The network's size: features of the first stage (x 4/3 per level) and the
    // number of poolings. The paper: 32 and 6. The default is half the paper's width:
    // 4x fewer multiply-adds, and the shipped weights of that width had 3x the
    // training steps of the paper-width ones (docs/rdae-training.md). Width 32 ships too.
    uint32_t width = 16;
    uint32_t levels = 6;
    // A safetensors file (samples/rdae_training writes them); empty: the weights hush
    // ships for this width and levels (rdae/builtin_weights.hpp).
    std::string weights;
    // Feature maps in rgba16f (fp32 arithmetic); off: rgba32f.
    bool halfPrecision = true;
    ChainBackSettings back;   // TAA on: "we apply TAA as a supplemental post-process" (Sec. 5.1)
};

template <class V> void describe(V&& v, RdaeSettings& s) {
    v.flatten(s.front);
    v.field("width", s.width, Range{1, 256});
    v.field("levels", s.levels, Range{1, 8});
    v.field("weights", s.weights);
    v.field("halfPrecision", s.halfPrecision);
    v.flatten(s.back);
}

class RdaeChain : public Chain {
public:
    explicit RdaeChain(const RdaeSettings& settings = {});
    std::string name() const override { return "rdae"; }
    std::vector<InputChannel> inputs() const override;
    // Reads and uploads the weights (once per chain). Throws hush::Error naming the
    // weights file and tensor on bad weights, and without the frame's camera.
    ChainOutputs build(NodeContext& ctx, const DenoiseInputs& inputs) override;
    const RdaeSettings& settings() const { return settings_; }
    RdaeArchitecture architecture() const { return {settings_.width, settings_.levels}; }
    RdaeTensorFormat tensorFormat() const;

private:
    RdaeSettings settings_;
    std::shared_ptr<const RdaeNetwork> network_;
};

// The weights a chain with these settings uses: the file, or the built-in ones.
// Throws hush::Error naming what is missing.
RdaeWeights loadRdaeWeights(const RdaeSettings& settings);

} // namespace hush::passes
