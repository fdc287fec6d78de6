#include <hush/passes/eaw/chain.hpp>

namespace hush::passes {

std::vector<InputChannel> EawChain::inputs() const {
    std::vector<InputChannel> channels{InputChannel::Color, InputChannel::Albedo, InputChannel::Normal,
                                       InputChannel::Position, InputChannel::Depth};
    if (settings_.separateEmission) channels.push_back(InputChannel::Emission);
    return channels;
}

ChainOutputs EawChain::build(NodeContext& ctx, const DenoiseInputs& raw) {
    const auto s = addSanitizePass(ctx, "eaw.sanitize", raw, settings_.sanitize);
    const auto& in = s.inputs;
    const graph::TextureHandle emission = settings_.separateEmission ? in[InputChannel::Emission] : graph::TextureHandle{};
    auto illumination = addDemodulatePass(ctx, "eaw.demodulate", in[InputChannel::Color], in[InputChannel::Albedo],
                                          settings_.demodulate, emission);
    // Depth makes the position weight scale-free (docs/passes/eaw.md).
    auto filtered = addEawAtrousLevels(ctx, "eaw.atrous", illumination, in[InputChannel::Normal],
                                       in[InputChannel::Position], in[InputChannel::Depth], settings_.atrous);
    auto radiance = addRemodulatePass(ctx, "eaw.remodulate", filtered, {}, in[InputChannel::Albedo],
                                      settings_.demodulate, emission);
    auto display = addTonemapPass(ctx, "eaw.tonemap", radiance, settings_.tonemap);
    ctx.graph.markOutput(radiance);
    ctx.graph.markOutput(display);
    return {display, radiance, s.counts};
}

} // namespace hush::passes
