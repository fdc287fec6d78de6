#include <hush/passes/bmfr/chain.hpp>

#include <algorithm>

#include <hush/passes/common/surface.hpp>

namespace hush::passes {

namespace {
bool readsRoughness(const BmfrFitSettings& fit) {
    return std::any_of(fit.features.begin(), fit.features.end(), bmfrNeedsRoughness);
}
} // namespace

BmfrChain::BmfrChain(const BmfrSettings& settings) : settings_(settings) {
    if (settings_.halfPrecision) {
        settings_.accumulate.format = rhi::Format::RGBA16Float;
        settings_.fit.format = rhi::Format::RGBA16Float;
        settings_.postAccumulate.format = rhi::Format::RGBA16Float;
    }
    // Fail at construction, not at the first build, on a weight outside (0, 1].
    bmfrAccumulateCountCap(settings_.accumulate);
    bmfrAccumulateCountCap(settings_.postAccumulate);
}

std::vector<InputChannel> BmfrChain::inputs() const {
    std::vector<InputChannel> channels{InputChannel::Color,    InputChannel::Albedo, InputChannel::Normal,
                                       InputChannel::Position, InputChannel::Depth,  InputChannel::Motion,
                                       InputChannel::MeshId};
    // Only an extra feature of Figs. 4-5 reads roughness; the paper's set does not.
    if (readsRoughness(settings_.fit)) channels.push_back(InputChannel::Roughness);
    if (settings_.separateEmission) channels.push_back(InputChannel::Emission);
    return channels;
}

ChainOutputs BmfrChain::build(NodeContext& ctx, const DenoiseInputs& raw) {
    const auto s = addSanitizePass(ctx, "bmfr.sanitize", raw, settings_.sanitize);
    const auto& in = s.inputs;
    // One reprojection decision per frame (Sec. 3.1's discard tests), read by both
    // accumulations (Sec. 3.3: the post stage reuses the first stage's decisions).
    const auto surface = addSurfacePass(ctx, "bmfr.surface", in[InputChannel::Normal], in[InputChannel::Depth],
                                        in[InputChannel::MeshId]);
    const auto reprojection = addReprojectPass(ctx, "bmfr.reproject", in[InputChannel::Motion], surface,
                                               surfaceHistory(ctx, "bmfr.surface"), settings_.reproject);

    const graph::TextureHandle emission = settings_.separateEmission ? in[InputChannel::Emission] : graph::TextureHandle{};
    const auto illumination = addDemodulatePass(ctx, "bmfr.demodulate", in[InputChannel::Color],
                                                in[InputChannel::Albedo], settings_.demodulate, emission);
    // (I) Only the noisy colour is accumulated: the features are the rasterised,
    // noise-free G-buffer of this frame (Sec. 3.1, Fig. 2).
    const auto accumulated =
        addBmfrAccumulatePass(ctx, "bmfr.accumulate", illumination, reprojection, settings_.accumulate);
    // (II) The guide holds every buffer a feature may read; the fit validates the set.
    BmfrGuide guide;
    guide.normal = in[InputChannel::Normal];
    guide.position = in[InputChannel::Position];
    guide.albedo = in[InputChannel::Albedo];
    guide.meshId = in[InputChannel::MeshId];
    if (readsRoughness(settings_.fit)) guide.roughness = in[InputChannel::Roughness];
    const auto fitted = addBmfrFitPass(ctx, "bmfr.fit", accumulated, guide, settings_.fit);
    // (III) The same decision texture as (I).
    const auto post =
        addBmfrAccumulatePass(ctx, "bmfr.post_accumulate", fitted, reprojection, settings_.postAccumulate);

    const auto radiance = addRemodulatePass(ctx, "bmfr.remodulate", post, {}, in[InputChannel::Albedo],
                                            settings_.demodulate, emission);
    auto display = addTonemapPass(ctx, "bmfr.tonemap", radiance, settings_.tonemap);
    if (settings_.useTaa)
        display = addTaaPass(ctx, "bmfr.taa", display, in[InputChannel::Motion], settings_.taa, reprojection);

    ctx.graph.markOutput(radiance);
    ctx.graph.markOutput(display);
    return {display, radiance, s.counts};
}

} // namespace hush::passes
