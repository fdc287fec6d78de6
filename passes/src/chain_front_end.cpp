#include <hush/passes/chain_front_end.hpp>

#include <algorithm>

#include <hush/passes/common/remodulate.hpp>

namespace hush::passes {

std::vector<InputChannel> mergeChannels(std::vector<InputChannel> a, const std::vector<InputChannel>& b) {
    a.insert(a.end(), b.begin(), b.end());
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    return a;
}

std::vector<InputChannel> ChainFrontEnd::inputs(const ChainFrontSettings& settings, bool reproject) {
    std::vector<InputChannel> channels{InputChannel::Albedo, InputChannel::Normal, InputChannel::Depth};
    if (reproject) channels = mergeChannels(channels, {InputChannel::Motion, InputChannel::MeshId});
    if (settings.separateEmission) channels = mergeChannels(channels, {InputChannel::Emission});
    return channels;
}

ChainFrontEnd::ChainFrontEnd(NodeContext& ctx, std::string chain, const DenoiseInputs& raw,
                             const ChainFrontSettings& settings, bool reproject)
    : ctx_(ctx), chain_(std::move(chain)), settings_(settings) {
    sanitized_ = addSanitizePass(ctx, chain_ + ".sanitize", raw, settings.sanitize);
    if (!reproject) return;
    const auto& in = sanitized_.inputs;
    surface_ = addSurfacePass(ctx, chain_ + ".surface", in[InputChannel::Normal], in[InputChannel::Depth],
                              in[InputChannel::MeshId]);
    reprojection_ = addReprojectPass(ctx, chain_ + ".reproject", in[InputChannel::Motion], surface_, settings.reproject);
}

graph::TextureHandle ChainFrontEnd::emission() const {
    return settings_.separateEmission ? sanitized_.inputs[InputChannel::Emission] : graph::TextureHandle{};
}

graph::TextureHandle ChainFrontEnd::demodulate(const std::string& stage, InputChannel term, bool carriesEmission) const {
    return addDemodulatePass(ctx_, chain_ + "." + stage, sanitized_.inputs[term], sanitized_.inputs[InputChannel::Albedo],
                             settings_.demodulate, carriesEmission ? emission() : graph::TextureHandle{});
}

graph::TextureHandle ChainFrontEnd::remodulate(graph::TextureHandle a, graph::TextureHandle b) const {
    return addRemodulatePass(ctx_, chain_ + ".remodulate", a, b, sanitized_.inputs[InputChannel::Albedo],
                             settings_.demodulate, emission());
}

} // namespace hush::passes
