#pragma once
// The shared back of every chain: from the method's filtered HDR radiance to what a
// user sees.
//   tonemap -> TAA (through the front end's reprojection decision) -> outputs
#include <string>

#include <hush/passes/chain.hpp>
#include <hush/passes/chain_front_end.hpp>
#include <hush/passes/common/taa.hpp>
#include <hush/passes/common/tonemap.hpp>
#include <hush/passes/settings.hpp>

namespace hush::passes {

struct ChainBackSettings {
    TonemapSettings tonemap;
    TaaSettings taa;
    bool useTaa = true;   // every temporal method's paper ends with TAA (Karis 2014)
};

template <class V> void describe(V&& v, ChainBackSettings& s) {
    v.section("tonemap", s.tonemap);
    v.section("taa", s.taa);
    v.field("useTaa", s.useTaa);
}

// The channels the back end reads beyond the front end's: motion for TAA.
std::vector<InputChannel> chainBackEndInputs(const ChainBackSettings& settings);

// Adds "<chain>.tonemap" and, with useTaa, "<chain>.taa" (which needs the front end
// built with reprojection: TAA must not drag history across an edge that moved onto
// another surface; docs/passes/display.md). Marks radiance and display as outputs.
ChainOutputs addChainBackEnd(NodeContext& ctx, const ChainFrontEnd& front, graph::TextureHandle radiance,
                             const ChainBackSettings& settings);

} // namespace hush::passes
