#pragma once
// RdaeInputChain: only what feeds the network (front end, demodulation, the input
// tensor), its tensor the chain's one output. The training data exporter runs it so
// that the network trains on exactly what it sees at inference (hush dataset,
// samples/rdae_training).
#include <hush/passes/chain.hpp>
#include <hush/passes/rdae/chain.hpp>

namespace hush::passes {

class RdaeInputChain : public Chain {
public:
    explicit RdaeInputChain(const RdaeSettings& settings = {});
    std::string name() const override { return "rdae-input"; }
    std::vector<InputChannel> inputs() const override;
    ChainOutputs build(NodeContext& ctx, const DenoiseInputs& inputs) override;
    // After build: the input tensor (kRdaeInputChannels at level 0, padded).
    const RdaeTensor& tensor() const { return tensor_; }
    RdaeTensorFormat tensorFormat() const { return RdaeChain(settings_).tensorFormat(); }

private:
    RdaeSettings settings_;
    RdaeTensor tensor_;
};

} // namespace hush::passes
