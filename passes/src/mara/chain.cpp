#include <hush/passes/mara/chain.hpp>

#include <hush/core/error.hpp>

namespace hush::passes {

namespace {
const std::vector<InputChannel> kGlossyChannels{InputChannel::Glossy, InputChannel::VirtualPos,
                                                InputChannel::Roughness};
} // namespace

std::vector<InputChannel> MaraChain::inputs() const {
    std::vector<InputChannel> own{InputChannel::Direct, InputChannel::Matte, InputChannel::Specular,
                                  InputChannel::Position};
    if (settings_.glossy == MaraGlossy::On) own = mergeChannels(own, kGlossyChannels);
    return mergeChannels(mergeChannels(own, ChainFrontEnd::inputs(settings_.front, true)),
                         chainBackEndInputs(settings_.back));
}

std::vector<InputChannel> MaraChain::optionalInputs() const {
    return settings_.glossy == MaraGlossy::On ? std::vector<InputChannel>{} : kGlossyChannels;
}

// Stages 3-7: the history loop (3 <-> 4), then the disocclusion-sized final filter.
graph::TextureHandle MaraChain::filterMatte(NodeContext& ctx, const ChainFrontEnd& front,
                                            const FrameCameraRef& camera) const {
    const auto position = front[InputChannel::Position];
    // Last frame's pre-bilateral output is the history (Sec. 3.4: "filtered (4) and
    // blended back into the historical buffer").
    const auto history = ctx.graph.history("mara.matte.history", fullSize());
    const auto temporal =
        addMaraMatteTemporalPass(ctx, "mara.matte.temporal", front[InputChannel::Matte], front[InputChannel::Motion],
                                 position, history, ctx.graph.history(position), camera, settings_.matteTemporal);
    const auto fedBack = addMaraSparseBilateralPass(ctx, "mara.matte.pre_bilateral", temporal, front.surface(),
                                                    position, {}, settings_.preBilateral);
    ctx.graph.bindHistory(history, fedBack);
    const auto radius = addMaraDisocclusionPass(ctx, "mara.matte.disocclusion", temporal, settings_.disocclusion);
    const auto shown = settings_.fireflySuppression ? addMaraMedianPass(ctx, "mara.matte.firefly", temporal) : temporal;
    return addMaraSparseBilateralPass(ctx, "mara.matte.bilateral", shown, front.surface(), position, radius,
                                      settings_.bilateral);
}

// Stages 8-10.
graph::TextureHandle MaraChain::filterGlossy(NodeContext& ctx, const ChainFrontEnd& front,
                                             const FrameCameraRef& camera) const {
    const auto virtualpos = front[InputChannel::VirtualPos];
    const auto temporal =
        addMaraGlossyTemporalPass(ctx, "mara.glossy.temporal", front[InputChannel::Glossy], virtualpos,
                                  ctx.graph.history(virtualpos), camera, settings_.glossyTemporal);
    return addMaraGlossyBilateralPasses(ctx, "mara.glossy.bilateral", temporal, front[InputChannel::Roughness],
                                        front.surface(), front[InputChannel::Position], settings_.glossyBilateral);
}

ChainOutputs MaraChain::build(NodeContext& ctx, const DenoiseInputs& raw) {
    if (!raw.camera)
        throw Error(ErrorKind::InvalidArgument, "chain 'mara' needs the frames' camera (the view direction for F, "
                                                "last frame's view for glossy reprojection)");
    const ChainFrontEnd front(ctx, "mara", raw, settings_.front, /*reproject=*/true);
    MaraComposeInputs compose{.direct = front[InputChannel::Direct],
                              .matte = filterMatte(ctx, front, raw.camera),
                              .glossy = {},
                              .albedo = front[InputChannel::Albedo],
                              .specular = front[InputChannel::Specular],
                              .surface = front.surface(),
                              .position = front[InputChannel::Position]};
    // The glossy branch exists whenever its layers do; what reads it decides whether it runs.
    const bool glossyLayers = raw.has(InputChannel::Glossy) && raw.has(InputChannel::VirtualPos) &&
                              raw.has(InputChannel::Roughness);
    if (glossyLayers) {
        const auto glossy = filterGlossy(ctx, front, raw.camera);
        if (settings_.glossy != MaraGlossy::Off) compose.glossy = glossy;
    }
    const auto radiance = addMaraComposePass(ctx, "mara.compose", compose, raw.camera);
    return addChainBackEnd(ctx, front, radiance, settings_.back);
}

} // namespace hush::passes
