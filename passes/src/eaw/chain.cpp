#include <hush/passes/eaw/chain.hpp>

namespace hush::passes {

std::vector<InputChannel> EawChain::inputs() const {
    // Reprojection only for TAA, which is off by default: EAW itself reads no history.
    const bool reproject = settings_.back.useTaa;
    return mergeChannels(mergeChannels({InputChannel::Color, InputChannel::Position},
                                       ChainFrontEnd::inputs(settings_.front, reproject)),
                         chainBackEndInputs(settings_.back));
}

ChainOutputs EawChain::build(NodeContext& ctx, const DenoiseInputs& raw) {
    const ChainFrontEnd front(ctx, "eaw", raw, settings_.front, /*reproject=*/settings_.back.useTaa);
    const auto illumination = front.demodulate("demodulate", InputChannel::Color);
    // Depth makes the position weight scale-free (docs/passes/eaw.md).
    const auto filtered = addEawAtrousLevels(ctx, "eaw.atrous", illumination, front[InputChannel::Normal],
                                             front[InputChannel::Position], front[InputChannel::Depth], settings_.atrous);
    return addChainBackEnd(ctx, front, front.remodulate(filtered), settings_.back);
}

} // namespace hush::passes
