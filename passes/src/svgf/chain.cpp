#include <hush/passes/svgf/chain.hpp>

#include <hush/core/error.hpp>

namespace hush::passes {

SvgfChain::SvgfChain(const SvgfSettings& settings) : settings_(settings) {
    if (settings.atrous.iterations < 1)
        throw Error(ErrorKind::InvalidArgument, "svgf: atrous.iterations must be at least 1 (level 0 is the colour "
                                                "history), got " + std::to_string(settings.atrous.iterations));
}

std::vector<InputChannel> SvgfChain::inputs() const {
    const std::vector<InputChannel> terms = settings_.splitLighting
                                                ? std::vector{InputChannel::Direct, InputChannel::Indirect}
                                                : std::vector{InputChannel::Color};
    return mergeChannels(mergeChannels(terms, ChainFrontEnd::inputs(settings_.front, true)),
                         chainBackEndInputs(settings_.back));
}

ChainOutputs SvgfChain::build(NodeContext& ctx, const DenoiseInputs& raw) {
    const ChainFrontEnd front(ctx, "svgf", raw, settings_.front, /*reproject=*/true);
    auto filterTerm = [&](const std::string& term, InputChannel channel, bool carriesEmission) {
        const std::string prefix = "svgf." + term;
        // The first a-trous level's output, a frame later, is the colour history (Sec. 4.1).
        const auto colorHistory = ctx.graph.history(prefix + ".color_history", fullSize());
        const auto illumination = front.demodulate(term + ".demodulate", channel, carriesEmission);
        const auto temporal = addSvgfTemporalPass(ctx, prefix + ".temporal", illumination, front.reprojection(),
                                                  colorHistory, settings_.temporal);
        const auto illumVariance =
            addSvgfVariancePass(ctx, prefix + ".variance", temporal, front.surface(), settings_.variance);
        const auto atrous = addSvgfAtrousLevels(ctx, prefix + ".atrous", illumVariance, front.surface(), settings_.atrous);
        ctx.graph.bindHistory(colorHistory, atrous.firstLevel);
        return atrous.filtered;
    };
    // Emission is part of direct light (or of the colour): that term gives it up.
    graph::TextureHandle radiance;
    if (settings_.splitLighting) {
        const auto direct = filterTerm("direct", InputChannel::Direct, true);
        const auto indirect = filterTerm("indirect", InputChannel::Indirect, false);
        radiance = front.remodulate(direct, indirect);
    } else {
        radiance = front.remodulate(filterTerm("color", InputChannel::Color, true));
    }
    return addChainBackEnd(ctx, front, radiance, settings_.back);
}

} // namespace hush::passes
