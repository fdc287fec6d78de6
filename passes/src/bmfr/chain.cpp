#include <hush/passes/bmfr/chain.hpp>

#include <algorithm>

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
    std::vector<InputChannel> own{InputChannel::Color, InputChannel::Position};
    // Only an extra feature of Figs. 4-5 reads roughness; the paper's set does not.
    if (readsRoughness(settings_.fit)) own.push_back(InputChannel::Roughness);
    return mergeChannels(mergeChannels(own, ChainFrontEnd::inputs(settings_.front, true)),
                         chainBackEndInputs(settings_.back));
}

ChainOutputs BmfrChain::build(NodeContext& ctx, const DenoiseInputs& raw) {
    // One reprojection decision per frame (Sec. 3.1's discard tests), read by both
    // accumulations (Sec. 3.3: the post stage reuses the first stage's decisions).
    const ChainFrontEnd front(ctx, "bmfr", raw, settings_.front, /*reproject=*/true);
    const auto illumination = front.demodulate("demodulate", InputChannel::Color);
    // (I) Only the noisy colour is accumulated: the features are the rasterised,
    // noise-free G-buffer of this frame (Sec. 3.1, Fig. 2).
    const auto accumulated =
        addBmfrAccumulatePass(ctx, "bmfr.accumulate", illumination, front.reprojection(), settings_.accumulate);
    // (II) The guide holds every buffer a feature may read; the fit validates the set.
    BmfrGuide guide;
    guide.normal = front[InputChannel::Normal];
    guide.position = front[InputChannel::Position];
    guide.albedo = front[InputChannel::Albedo];
    guide.meshId = front[InputChannel::MeshId];
    if (readsRoughness(settings_.fit)) guide.roughness = front[InputChannel::Roughness];
    const auto fitted = addBmfrFitPass(ctx, "bmfr.fit", accumulated, guide, settings_.fit);
    // (III) The same decision texture as (I).
    const auto post =
        addBmfrAccumulatePass(ctx, "bmfr.post_accumulate", fitted, front.reprojection(), settings_.postAccumulate);
    return addChainBackEnd(ctx, front, front.remodulate(post), settings_.back);
}

} // namespace hush::passes
