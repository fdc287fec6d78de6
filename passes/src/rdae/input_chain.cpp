#include <hush/passes/rdae/input_chain.hpp>

#include <hush/core/error.hpp>
#include <hush/passes/rdae/input.hpp>

namespace hush::passes {

RdaeInputChain::RdaeInputChain(const RdaeSettings& settings) : settings_(settings) {
    settings_.back.useTaa = false;   // nothing temporal: no reprojection inputs
}

std::vector<InputChannel> RdaeInputChain::inputs() const {
    return mergeChannels({InputChannel::Color, InputChannel::Roughness}, ChainFrontEnd::inputs(settings_.front, false));
}

ChainOutputs RdaeInputChain::build(NodeContext& ctx, const DenoiseInputs& raw) {
    if (!raw.camera) throw Error(ErrorKind::InvalidArgument, "chain 'rdae-input' needs the frames' camera");
    const ChainFrontEnd front(ctx, "rdae", raw, settings_.front, false);
    const auto illumination = front.demodulate("demodulate", InputChannel::Color);
    tensor_ = addRdaeInputPass(ctx, "rdae.input", illumination, front[InputChannel::Normal], front[InputChannel::Depth],
                               front[InputChannel::Roughness], raw.camera, tensorFormat());
    ctx.graph.markOutput(tensor_.texture);
    ChainOutputs out;
    out.sanitizeCounts = front.sanitizeCounts();
    ctx.graph.markOutput(out.sanitizeCounts);
    return out;
}

} // namespace hush::passes
