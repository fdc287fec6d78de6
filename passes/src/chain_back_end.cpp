#include <hush/passes/chain_back_end.hpp>

#include <hush/core/error.hpp>

namespace hush::passes {

std::vector<InputChannel> chainBackEndInputs(const ChainBackSettings& settings) {
    if (settings.useTaa) return {InputChannel::Motion};
    return {};
}

ChainOutputs addChainBackEnd(NodeContext& ctx, const ChainFrontEnd& front, graph::TextureHandle radiance,
                             const ChainBackSettings& settings) {
    const std::string& chain = front.chain();
    auto display = addTonemapPass(ctx, chain + ".tonemap", radiance, settings.tonemap);
    if (settings.useTaa) {
        if (!front.reprojection().valid())
            throw Error(ErrorKind::InvalidArgument, "chain '" + chain + "': TAA needs the front end's reprojection "
                                                    "decision; build the front end with reprojection");
        display = addTaaPass(ctx, chain + ".taa", display, front[InputChannel::Motion], settings.taa,
                             front.reprojection());
    }
    ctx.graph.markOutput(radiance);
    ctx.graph.markOutput(display);
    return {display, radiance, front.sanitizeCounts()};
}

} // namespace hush::passes
