#include <hush/passes/svgf/chain.hpp>

#include <hush/passes/common/surface.hpp>
#include <hush/core/error.hpp>

namespace hush::passes {

SvgfChain::SvgfChain(const SvgfSettings& settings) : settings_(settings) {
    // The first a-trous level is the colour history (Sec. 4.1), so there must be one.
    if (settings.atrous.iterations < 1)
        throw Error(ErrorKind::InvalidArgument, "svgf: atrous.iterations must be at least 1 (level 0 is the colour "
                                                "history), got " + std::to_string(settings.atrous.iterations));
}

std::vector<InputChannel> SvgfChain::inputs() const {
    std::vector<InputChannel> channels;
    if (settings_.splitLighting) {
        channels = {InputChannel::Direct, InputChannel::Indirect};
    } else {
        channels = {InputChannel::Color};
    }
    for (auto c : {InputChannel::Albedo, InputChannel::Normal, InputChannel::Depth, InputChannel::Motion,
                   InputChannel::MeshId})
        channels.push_back(c);
    if (settings_.separateEmission) channels.push_back(InputChannel::Emission);
    return channels;
}

ChainOutputs SvgfChain::build(NodeContext& ctx, const DenoiseInputs& raw) {
    const auto s = addSanitizePass(ctx, "svgf.sanitize", raw, settings_.sanitize);
    const auto& in = s.inputs;
    const auto surface = addSurfacePass(ctx, "svgf.surface", in[InputChannel::Normal], in[InputChannel::Depth],
                                        in[InputChannel::MeshId]);
    const auto reprojection = addReprojectPass(ctx, "svgf.reproject", in[InputChannel::Motion], surface,
                                               surfaceHistory(ctx, "svgf.surface"), settings_.reproject);

    // Emission (part of direct, or of colour) is taken out of that term and added back at the end.
    const graph::TextureHandle emission = settings_.separateEmission ? in[InputChannel::Emission] : graph::TextureHandle{};
    auto filterTerm = [&](const std::string& term, InputChannel channel, graph::TextureHandle termEmission) {
        const std::string prefix = "svgf." + term;
        auto illumination = addDemodulatePass(ctx, prefix + ".demodulate", in[channel], in[InputChannel::Albedo],
                                              settings_.demodulate, termEmission);
        // The first a-trous level's output feeds back as the colour history (Sec. 4.1).
        const std::string atrousName = prefix + ".atrous";
        auto temporal = addSvgfTemporalPass(ctx, prefix + ".temporal", illumination, reprojection,
                                            atrousName + ".level.0", settings_.temporal);
        auto illumVariance = addSvgfVariancePass(ctx, prefix + ".variance", temporal, surface, settings_.variance);
        return addSvgfAtrousLevels(ctx, atrousName, illumVariance, surface, settings_.atrous).filtered;
    };

    graph::TextureHandle radiance;
    if (settings_.splitLighting) {
        auto direct = filterTerm("direct", InputChannel::Direct, emission);
        auto indirect = filterTerm("indirect", InputChannel::Indirect, {});
        radiance = addRemodulatePass(ctx, "svgf.remodulate", direct, indirect, in[InputChannel::Albedo],
                                     settings_.demodulate, emission);
    } else {
        auto color = filterTerm("color", InputChannel::Color, emission);
        radiance = addRemodulatePass(ctx, "svgf.remodulate", color, {}, in[InputChannel::Albedo], settings_.demodulate,
                                     emission);
    }
    auto display = addTonemapPass(ctx, "svgf.tonemap", radiance, settings_.tonemap);
    // The reprojection decision keeps TAA from dragging history across an edge that
    // moved into another surface (docs/passes/display.md).
    if (settings_.useTaa)
        display = addTaaPass(ctx, "svgf.taa", display, in[InputChannel::Motion], settings_.taa, reprojection);

    ctx.graph.markOutput(radiance);
    ctx.graph.markOutput(display);
    return {display, radiance, s.counts};
}

} // namespace hush::passes
