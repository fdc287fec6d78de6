#include <hush/passes/rdae/chain.hpp>

#include <hush/core/error.hpp>
#include <hush/passes/rdae/builtin_weights.hpp>
#include <hush/passes/rdae/input.hpp>
#include <hush/passes/rdae/output.hpp>

namespace hush::passes {

RdaeWeights loadRdaeWeights(const RdaeSettings& settings) {
    if (!settings.weights.empty()) return RdaeWeights::read(settings.weights);
    const RdaeArchitecture wanted{settings.width, settings.levels};
    if (const auto builtin = findRdaeBuiltinWeights(wanted)) return RdaeWeights::parse(builtin->bytes, builtin->name);
    std::string list;
    for (const auto& w : rdaeBuiltinWeights())
        list += (list.empty() ? "" : ", ") + ("width " + std::to_string(w.architecture.width) + " levels " +
                                                std::to_string(w.architecture.levels));
    throw Error(ErrorKind::NotFound, "rdae: no built-in weights for width " + std::to_string(settings.width) +
                                         " and levels " + std::to_string(settings.levels) + " (built in: " +
                                         (list.empty() ? "none" : list) +
                                         "); train some (samples/rdae_training) and set 'weights' to the file");
}

RdaeChain::RdaeChain(const RdaeSettings& settings) : settings_(settings) { architecture().validate(); }

RdaeTensorFormat RdaeChain::tensorFormat() const {
    return {.levels = settings_.levels,
            .format = settings_.halfPrecision ? rhi::Format::RGBA16Float : rhi::Format::RGBA32Float};
}

std::vector<InputChannel> RdaeChain::inputs() const {
    return mergeChannels(mergeChannels({InputChannel::Color, InputChannel::Roughness},
                                       ChainFrontEnd::inputs(settings_.front, settings_.back.useTaa)),
                         chainBackEndInputs(settings_.back));
}

ChainOutputs RdaeChain::build(NodeContext& ctx, const DenoiseInputs& raw) {
    if (!raw.camera)
        throw Error(ErrorKind::InvalidArgument, "chain 'rdae' needs the frames' camera (view-space normals)");
    if (!network_)
        network_ = std::make_shared<RdaeNetwork>(ctx.pipelines.device(), loadRdaeWeights(settings_), architecture());
    const ChainFrontEnd front(ctx, "rdae", raw, settings_.front, /*reproject=*/settings_.back.useTaa);
    const auto format = tensorFormat();
    const auto illumination = front.demodulate("demodulate", InputChannel::Color);
    const auto input = addRdaeInputPass(ctx, "rdae.input", illumination, front[InputChannel::Normal],
                                        front[InputChannel::Depth], front[InputChannel::Roughness], raw.camera, format);
    const auto network = addRdaeNetwork(ctx, "rdae", input, *network_, format);
    const auto filtered = addRdaeOutputPass(ctx, "rdae.output", network);
    return addChainBackEnd(ctx, front, front.remodulate(filtered), settings_.back);
}

} // namespace hush::passes
